// Stage 1, curves: supervoxels merged into smooth surfaces, and the points where those surfaces
// meet (normal edges), linked into curves (linking is in curve_linking.cpp).
#include "symmetry_segmentation/symmetry/normal_edge_curves.h"

#include <cmath>
#include <map>

#include <pcl/kdtree/kdtree_flann.h>
#include <pcl/segmentation/supervoxel_clustering.h>

#include "disjoint_sets.h"
#include "symmetry_segmentation/symmetry/pipeline_state.h"

namespace symmetry_segmentation {
namespace {

using SupervoxelPoint = pcl::PointXYZRGBA;

/// Supervoxel label per working-cloud point (0 = not in any supervoxel).
std::vector<int> supervoxelLabels(const Cloud& cloud, const NormalEdgeCurveParams& params) {
  auto points = std::make_shared<pcl::PointCloud<SupervoxelPoint>>();
  auto normals = std::make_shared<pcl::PointCloud<pcl::Normal>>();
  points->reserve(cloud.size());
  normals->reserve(cloud.size());
  for (const PointT& p : cloud.points) {
    SupervoxelPoint q;
    q.x = p.x;
    q.y = p.y;
    q.z = p.z;
    q.r = p.r;
    q.g = p.g;
    q.b = p.b;
    q.a = 255;
    points->push_back(q);
    // Our normals are oriented already; given them, PCL does not flip normals toward the origin.
    normals->push_back(pcl::Normal(p.normal_x, p.normal_y, p.normal_z));
  }

  pcl::SupervoxelClustering<SupervoxelPoint> supervoxels(params.supervoxel_voxel, params.supervoxel_seed);
  supervoxels.setUseSingleCameraTransform(false);
  supervoxels.setInputCloud(points);
  supervoxels.setNormalCloud(normals);
  // Normal edges are geometric: colour must not move supervoxel borders.
  supervoxels.setColorImportance(0.0f);
  supervoxels.setSpatialImportance(0.4f);
  supervoxels.setNormalImportance(1.0f);
  std::map<std::uint32_t, pcl::Supervoxel<SupervoxelPoint>::Ptr> clusters;
  supervoxels.extract(clusters);

  const auto labeled = supervoxels.getLabeledCloud();  // Input order.
  std::vector<int> labels(cloud.size(), 0);
  for (std::size_t i = 0; i < labels.size() && i < labeled->size(); ++i) {
    labels[i] = static_cast<int>(labeled->points[i].label);
  }
  return labels;
}

}  // namespace

std::vector<int> mergedSegmentLabels(const Cloud& cloud, const NormalEdgeCurveParams& params) {
  if (cloud.empty()) return {};
  const std::vector<int> supervoxel = supervoxelLabels(cloud, params);

  int max_label = 0;
  for (int label : supervoxel) max_label = std::max(max_label, label);
  // Supervoxel normal = mean of our oriented point normals (PCL's own may be flipped).
  std::vector<Eigen::Vector3f> mean_normal(max_label + 1, Eigen::Vector3f::Zero());
  for (std::size_t i = 0; i < cloud.size(); ++i) {
    mean_normal[supervoxel[i]] += cloud.points[i].getNormalVector3fMap();
  }
  for (auto& n : mean_normal) {
    if (n.norm() > 1e-6f) n.normalize();
  }

  // Supervoxels are adjacent where their points touch; compare the normals there too. On a
  // smooth surface they agree however curved it is (the mean normals of 3 cm supervoxels on a
  // 6 cm radius can differ by ~30 degrees), across an edge they do not.
  pcl::KdTreeFLANN<PointT> tree;
  tree.setInputCloud(Cloud::ConstPtr(&cloud, [](const Cloud*) {}));
  const float contact_radius = 1.5f * params.supervoxel_voxel;
  std::map<std::pair<int, int>, std::pair<double, int>> contact;  // Sum of normal dots, count.
  std::vector<int> neighbours;
  std::vector<float> squared_distances;
  for (std::size_t i = 0; i < cloud.size(); ++i) {
    const int a = supervoxel[i];
    if (a == 0) continue;
    tree.radiusSearch(cloud.points[i], contact_radius, neighbours, squared_distances);
    for (int j : neighbours) {
      const int b = supervoxel[j];
      if (b <= a) continue;  // Each touching pair once, from its lower label.
      auto& [dot_sum, count] = contact[{a, b}];
      dot_sum += cloud.points[i].getNormalVector3fMap().dot(cloud.points[j].getNormalVector3fMap());
      ++count;
    }
  }

  // Collinear mean normals merge (flat faces). Smoothly touching supervoxels merge too, unless
  // their mean normals are far apart: a supervoxel bent over an edge touches both faces smoothly
  // and must not glue them together.
  const float min_cos = std::cos(params.merge_normal_angle_deg * static_cast<float>(M_PI) / 180.0f);
  const float min_mean_cos = std::cos(params.curved_merge_angle_deg * static_cast<float>(M_PI) / 180.0f);
  DisjointSets sets(max_label + 1);
  for (const auto& [pair, sums] : contact) {
    const auto [a, b] = pair;
    const float mean_cos = mean_normal[a].dot(mean_normal[b]);
    const bool smooth_contact = sums.first / sums.second > min_cos && mean_cos > min_mean_cos;
    if (mean_cos > min_cos || smooth_contact) sets.unite(a, b);
  }

  // Compact labels 1..K in order of first appearance, so they do not depend on PCL's numbering.
  std::vector<int> compact(max_label + 1, 0);
  int next = 0;
  std::vector<int> labels(cloud.size(), 0);
  for (std::size_t i = 0; i < cloud.size(); ++i) {
    if (supervoxel[i] == 0) continue;
    int& label = compact[sets.find(supervoxel[i])];
    if (label == 0) label = ++next;
    labels[i] = label;
  }
  return labels;
}

std::vector<int> boundaryPoints(const Cloud& cloud, const std::vector<int>& labels,
                                const NormalEdgeCurveParams& params) {
  std::vector<int> boundary;
  if (cloud.empty()) return boundary;
  pcl::KdTreeFLANN<PointT> tree;
  tree.setInputCloud(Cloud::ConstPtr(&cloud, [](const Cloud*) {}));  // Borrowed, not copied.
  std::vector<int> neighbours;
  std::vector<float> squared_distances;
  for (std::size_t i = 0; i < cloud.size(); ++i) {
    if (labels[i] == 0) continue;
    tree.radiusSearch(cloud.points[i], params.boundary_radius, neighbours, squared_distances);
    for (int j : neighbours) {
      if (labels[j] != 0 && labels[j] != labels[i]) {
        boundary.push_back(static_cast<int>(i));
        break;
      }
    }
  }
  return boundary;
}

std::vector<Curve> extractNormalEdgeCurves(const Cloud& cloud, const NormalEdgeCurveParams& params) {
  return extractNormalEdgeCurves(cloud, mergedSegmentLabels(cloud, params), params);
}

std::vector<Curve> extractNormalEdgeCurves(const Cloud& cloud, const std::vector<int>& labels,
                                           const NormalEdgeCurveParams& params) {
  const std::vector<int> boundary = boundaryPoints(cloud, labels, params);
  std::vector<Curve> curves = linkCurves(cloud, boundary, labels, params);
  useEdgeTangents(cloud, labels, params, curves);
  return curves;
}

void NormalEdgeCurveStage::run(PipelineState& state) const {
  state.surfaces = mergedSegmentLabels(*state.cloud, params_);
  state.curves = extractNormalEdgeCurves(*state.cloud, state.surfaces, params_);
  state.count("curves", state.curves.size());
}

}  // namespace symmetry_segmentation
