// LCCP baseline: supervoxels at full resolution over the points above the table, then
// locally convex connected patches, as in the paper's comparison.
#include <map>

#include <pcl/segmentation/lccp_segmentation.h>
#include <pcl/segmentation/supervoxel_clustering.h>

#include "symmetry_segmentation/baseline_segmenters.h"
#include "symmetry_segmentation/object_bottoms.h"
#include "symmetry_segmentation/segment_order.h"
#include "symmetry_segmentation/object_box.h"
#include "symmetry_segmentation/stopwatch.h"

namespace symmetry_segmentation {
namespace {
using LccpPoint = pcl::PointXYZRGBA;
}

SegmentationResult LccpSegmenter::segment(const Scene& scene) const {
  Stopwatch total, stage;
  SegmentationResult result;
  result.input_points = scene.size();
  const PreprocessedScene prepared = preprocess(scene, preprocessing_);
  result.support = supportSurface(prepared);
  result.timing_ms.emplace_back("preprocess", stage.lap());

  // PCL's supervoxels orient normals toward the coordinate origin, so work in a frame centred
  // on the sensor, and hand over the oriented normals preprocessing already has.
  const Eigen::Vector3f& sensor = prepared.viewpoint;
  auto points = std::make_shared<pcl::PointCloud<LccpPoint>>();
  auto normals = std::make_shared<pcl::PointCloud<pcl::Normal>>();
  points->reserve(prepared.kept_input_indices.size());
  normals->reserve(prepared.kept_input_indices.size());
  for (int index : prepared.kept_input_indices) {
    const auto& p = scene.cloud->points[index];
    const auto& voxel = prepared.cloud->points[prepared.input_to_voxel[index]];
    normals->push_back(pcl::Normal(voxel.normal_x, voxel.normal_y, voxel.normal_z));
    LccpPoint q;
    q.x = p.x - sensor.x();
    q.y = p.y - sensor.y();
    q.z = p.z - sensor.z();
    q.r = p.r;
    q.g = p.g;
    q.b = p.b;
    q.a = 255;
    points->push_back(q);
  }

  pcl::SupervoxelClustering<LccpPoint> supervoxels(params_.voxel_resolution, params_.seed_resolution);
  supervoxels.setUseSingleCameraTransform(false);
  supervoxels.setInputCloud(points);
  supervoxels.setNormalCloud(normals);
  supervoxels.setColorImportance(params_.color_importance);
  supervoxels.setSpatialImportance(params_.spatial_importance);
  supervoxels.setNormalImportance(params_.normal_importance);
  std::map<std::uint32_t, pcl::Supervoxel<LccpPoint>::Ptr> clusters;
  supervoxels.extract(clusters);
  std::multimap<std::uint32_t, std::uint32_t> adjacency;
  supervoxels.getSupervoxelAdjacency(adjacency);
  result.timing_ms.emplace_back("supervoxels", stage.lap());

  pcl::LCCPSegmentation<LccpPoint> lccp;
  lccp.setConcavityToleranceThreshold(params_.concavity_tolerance);
  lccp.setSanityCheck(params_.use_sanity_criterion);
  lccp.setSmoothnessCheck(true, params_.voxel_resolution, params_.seed_resolution, params_.smoothness_threshold);
  lccp.setKFactor(params_.use_extended_convexity ? 1 : 0);
  lccp.setMinSegmentSize(static_cast<unsigned int>(std::max(0, params_.min_segment_size)));
  lccp.setInputSupervoxels(clusters, adjacency);
  lccp.segment();
  auto labeled = supervoxels.getLabeledCloud();
  lccp.relabelCloud(*labeled);

  // labeled is in the order of `points`, i.e. of kept_input_indices.
  std::map<std::uint32_t, std::vector<int>> by_label;
  for (std::size_t i = 0; i < labeled->size() && i < prepared.kept_input_indices.size(); ++i) {
    const std::uint32_t label = labeled->points[i].label;
    if (label != 0) by_label[label].push_back(prepared.kept_input_indices[i]);
  }
  for (auto& [label, indices] : by_label) {
    if (static_cast<int>(indices.size()) < params_.min_points) continue;
    Segment segment;
    segment.indices = std::move(indices);
    result.segments.push_back(std::move(segment));
  }
  if (params_.restore_object_bottoms) {
    restoreObjectBottoms(scene, prepared, preprocessing_.voxel_size, result.segments, bottoms_);
  }
  sortSegmentsBySize(result.segments);
  addObjectBoxes(scene, result);
  result.timing_ms.emplace_back("lccp", stage.lap());
  result.timing_ms.emplace_back("total", total.elapsedMs());
  return result;
}

}  // namespace symmetry_segmentation
