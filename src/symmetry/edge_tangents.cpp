// Tangents of normal-edge curves from the surfaces that meet there: the edge runs along
// n_a x n_b. On a 1 cm voxel cloud an edge not aligned with the grid is a staircase, and the
// principal direction of a few curve points is off by up to ~15 degrees; the cross product of
// the two sides' normals is not (normal smoothing tilts both within the plane normal to the edge).
#include <cmath>
#include <map>

#include <pcl/kdtree/kdtree_flann.h>

#include "symmetry_segmentation/symmetry/normal_edge_curves.h"

namespace symmetry_segmentation {

void useEdgeTangents(const Cloud& cloud, const std::vector<int>& labels, const NormalEdgeCurveParams& params,
                     std::vector<Curve>& curves) {
  pcl::KdTreeFLANN<PointT> tree;
  tree.setInputCloud(Cloud::ConstPtr(&cloud, [](const Cloud*) {}));
  // Sides meeting at less than min_edge_angle_deg give no reliable cross product: the curve
  // tangent stays.
  const float min_sin = std::sin(params.min_edge_angle_deg * static_cast<float>(M_PI) / 180.0f);
  std::vector<int> neighbours;
  std::vector<float> squared_distances;
  for (Curve& curve : curves) {
    for (std::size_t k = 0; k < curve.points.size(); ++k) {
      const int index = curve.points[k];
      const int own = labels[index];
      tree.radiusSearch(cloud.points[index], params.boundary_radius, neighbours, squared_distances);
      // The other side is the segment with the most points nearby (ties: lower label).
      std::map<int, std::pair<int, Eigen::Vector3f>> sides;  // label -> count, normal sum
      for (int j : neighbours) {
        if (labels[j] == 0) continue;
        auto& side = sides.try_emplace(labels[j], 0, Eigen::Vector3f::Zero()).first->second;
        ++side.first;
        side.second += cloud.points[j].getNormalVector3fMap();
      }
      const auto own_side = sides.find(own);
      if (own_side == sides.end()) continue;
      int other = 0, best = 0;
      for (const auto& [label, side] : sides) {
        if (label != own && side.first > best) {
          best = side.first;
          other = label;
        }
      }
      if (other == 0) continue;
      const Eigen::Vector3f edge =
          own_side->second.second.normalized().cross(sides.at(other).second.normalized());
      if (edge.norm() > min_sin) curve.tangents[k] = edge.normalized();
    }
  }
}

}  // namespace symmetry_segmentation
