// Stage curves of the symmetry method on boxes and cylinders: merged segments, boundary points on
// the edges only, and curves whose tangents follow the edges.
#include <gtest/gtest.h>

#include <cmath>
#include <set>

#include "symmetry_segmentation/symmetry/normal_edge_curves.h"
#include "test_clouds.h"

namespace ss = symmetry_segmentation;

namespace {

const Eigen::Vector3f kBoxSize(0.20f, 0.16f, 0.14f);

struct Segment3 {
  Eigen::Vector3f a, b;
  Eigen::Vector3f direction() const { return (b - a).normalized(); }
  float distance(const Eigen::Vector3f& p) const {
    const Eigen::Vector3f d = b - a;
    const float t = std::clamp((p - a).dot(d) / d.squaredNorm(), 0.0f, 1.0f);
    return (a + t * d - p).norm();
  }
};

/// The eight edges where two visible faces of the box (min corner at the origin) meet.
std::vector<Segment3> boxEdges(const Eigen::Vector3f& size) {
  const float x = size.x(), y = size.y(), z = size.z();
  return {{{0, 0, z}, {x, 0, z}}, {{0, y, z}, {x, y, z}}, {{0, 0, z}, {0, y, z}}, {{x, 0, z}, {x, y, z}},
          {{0, 0, 0}, {0, 0, z}}, {{x, 0, 0}, {x, 0, z}}, {{0, y, 0}, {0, y, z}}, {{x, y, 0}, {x, y, z}}};
}

float distanceToEdges(const std::vector<Segment3>& edges, const Eigen::Vector3f& p, int* nearest = nullptr) {
  float best = 1e9f;
  for (std::size_t e = 0; e < edges.size(); ++e) {
    const float d = edges[e].distance(p);
    if (d < best) {
      best = d;
      if (nearest) *nearest = static_cast<int>(e);
    }
  }
  return best;
}

ss::Cloud boxCloud(float spacing) {
  ss::Cloud cloud;
  test_clouds::addBox(cloud, Eigen::Vector3f::Zero(), kBoxSize, spacing);
  return cloud;
}

/// Side and top cap of an upright cylinder on z = 0 around (cx, cy), outward normals.
ss::Cloud cylinderCloud(float radius, float height, float spacing) {
  ss::Cloud cloud;
  auto add = [&](const Eigen::Vector3f& p, const Eigen::Vector3f& n) {
    ss::PointT q;
    q.getVector3fMap() = p;
    q.getNormalVector3fMap() = n;
    q.r = q.g = q.b = 200;
    cloud.push_back(q);
  };
  const int around = static_cast<int>(std::round(2.0f * static_cast<float>(M_PI) * radius / spacing));
  for (float z = spacing; z < height - 1e-6f; z += spacing) {
    for (int k = 0; k < around; ++k) {
      const float a = 2.0f * static_cast<float>(M_PI) * k / around;
      add({radius * std::cos(a), radius * std::sin(a), z}, {std::cos(a), std::sin(a), 0.0f});
    }
  }
  for (float x = -radius; x <= radius + 1e-6f; x += spacing) {
    for (float y = -radius; y <= radius + 1e-6f; y += spacing) {
      if (x * x + y * y <= radius * radius) add({x, y, height}, Eigen::Vector3f::UnitZ());
    }
  }
  return cloud;
}

}  // namespace

TEST(MergedSegments, FlatFacesAreWholeAndDistinct) {
  const ss::Cloud cloud = boxCloud(0.01f);
  const ss::NormalEdgeCurveParams params;
  const auto labels = ss::mergedSegmentLabels(cloud, params);
  ASSERT_EQ(labels.size(), cloud.size());
  // Points well inside each face (away from the edges, where supervoxels may straddle).
  std::map<std::string, std::set<int>> face_labels;
  for (std::size_t i = 0; i < cloud.size(); ++i) {
    const Eigen::Vector3f p = cloud.points[i].getVector3fMap();
    if (distanceToEdges(boxEdges(kBoxSize), p) < 0.035f || p.z() < 0.035f) continue;
    const Eigen::Vector3f n = cloud.points[i].getNormalVector3fMap();
    const std::string face = n.z() > 0.5f ? "top" : n.x() > 0.5f ? "+x" : n.x() < -0.5f ? "-x" : n.y() > 0.5f ? "+y" : "-y";
    face_labels[face].insert(labels[i]);
  }
  ASSERT_EQ(face_labels.size(), 5u);
  std::set<int> distinct;
  for (const auto& [face, set] : face_labels) {
    EXPECT_EQ(set.size(), 1u) << face << " is cut into " << set.size() << " segments";
    EXPECT_EQ(set.count(0), 0u) << face;
    distinct.insert(*set.begin());
  }
  EXPECT_EQ(distinct.size(), 5u) << "faces at right angles must not merge";
}

TEST(MergedSegments, SmoothCylinderSideIsOneSegment) {
  // Mean normals of neighbouring 3 cm supervoxels on this side differ by ~17 degrees, more than
  // merge_normal_angle_deg: only their smooth contact merges them.
  const ss::Cloud cloud = cylinderCloud(0.10f, 0.14f, 0.01f);
  const auto labels = ss::mergedSegmentLabels(cloud, ss::NormalEdgeCurveParams{});
  std::set<int> side, top;
  for (std::size_t i = 0; i < cloud.size(); ++i) {
    const auto& p = cloud.points[i];
    if (p.normal_z > 0.5f && std::hypot(p.x, p.y) < 0.06f) top.insert(labels[i]);
    if (p.normal_z < 0.5f && p.z > 0.03f && p.z < 0.11f) side.insert(labels[i]);
  }
  EXPECT_EQ(side.size(), 1u);
  EXPECT_EQ(top.size(), 1u);
  EXPECT_NE(*side.begin(), *top.begin());
}

TEST(BoundaryPoints, LieOnTheBoxEdgesOnly) {
  for (float spacing : {0.01f, 0.005f}) {
    const ss::Cloud cloud = boxCloud(spacing);
    const ss::NormalEdgeCurveParams params;
    const auto labels = ss::mergedSegmentLabels(cloud, params);
    const auto boundary = ss::boundaryPoints(cloud, labels, params);
    ASSERT_FALSE(boundary.empty());
    const auto edges = boxEdges(kBoxSize);
    std::vector<int> per_edge(edges.size(), 0);
    for (int index : boundary) {
      int nearest = -1;
      const float d = distanceToEdges(edges, cloud.points[index].getVector3fMap(), &nearest);
      // Supervoxels may straddle an edge, so a merged border can sit a supervoxel off it.
      EXPECT_LT(d, params.supervoxel_seed + params.boundary_radius) << "spacing " << spacing;
      ++per_edge[nearest];
    }
    for (std::size_t e = 0; e < edges.size(); ++e) {
      EXPECT_GT(per_edge[e], 5) << "edge " << e << " spacing " << spacing;
    }
    // The middle of the top face is no boundary.
    const std::set<int> boundary_set(boundary.begin(), boundary.end());
    for (std::size_t i = 0; i < cloud.size(); ++i) {
      const auto& p = cloud.points[i];
      if (p.normal_z > 0.5f && std::fabs(p.x - 0.10f) < 0.03f && std::fabs(p.y - 0.08f) < 0.02f) {
        EXPECT_EQ(boundary_set.count(static_cast<int>(i)), 0u);
      }
    }
  }
}

TEST(NormalEdgeCurves, FollowTheBoxEdges) {
  for (float spacing : {0.01f, 0.005f}) {
    const ss::Cloud cloud = boxCloud(spacing);
    const ss::NormalEdgeCurveParams params;
    const auto curves = ss::extractNormalEdgeCurves(cloud, params);
    ASSERT_FALSE(curves.empty());
    const auto edges = boxEdges(kBoxSize);
    std::set<int> used;
    int checked = 0, parallel = 0;
    for (const auto& curve : curves) {
      ASSERT_EQ(curve.points.size(), curve.tangents.size());
      EXPECT_GE(static_cast<int>(curve.points.size()), params.min_curve_points);
      for (std::size_t k = 0; k < curve.points.size(); ++k) {
        EXPECT_TRUE(used.insert(curve.points[k]).second) << "curves must be disjoint";
        EXPECT_NEAR(curve.tangents[k].norm(), 1.0f, 1e-4f);
        if (k > 0) {  // Ordered: consecutive points are linked.
          const float step = (cloud.points[curve.points[k]].getVector3fMap() -
                              cloud.points[curve.points[k - 1]].getVector3fMap()).norm();
          EXPECT_LE(step, params.curve_link_radius + 1e-5f);
        }
        // Tangents away from the corners must follow the edge.
        const Eigen::Vector3f p = cloud.points[curve.points[k]].getVector3fMap();
        int nearest = -1;
        distanceToEdges(edges, p, &nearest);
        const Segment3& edge = edges[nearest];
        const Eigen::Vector3f d = edge.direction();
        const float along = (p - edge.a).dot(d);
        if (along < 0.04f || along > (edge.b - edge.a).norm() - 0.04f || p.z() < 0.04f) continue;
        ++checked;
        if (std::fabs(curve.tangents[k].dot(d)) > std::cos(15.0f * static_cast<float>(M_PI) / 180.0f)) ++parallel;
      }
    }
    ASSERT_GT(checked, 20) << "spacing " << spacing;
    EXPECT_GT(parallel, 0.85 * checked) << "spacing " << spacing << ": " << parallel << " of " << checked;
  }
}

TEST(NormalEdgeCurves, DeterministicAndEmptySafe) {
  const ss::Cloud cloud = boxCloud(0.01f);
  const ss::NormalEdgeCurveParams params;
  const auto first = ss::extractNormalEdgeCurves(cloud, params);
  const auto second = ss::extractNormalEdgeCurves(cloud, params);
  ASSERT_EQ(first.size(), second.size());
  for (std::size_t c = 0; c < first.size(); ++c) EXPECT_EQ(first[c].points, second[c].points);
  EXPECT_TRUE(ss::extractNormalEdgeCurves(ss::Cloud(), params).empty());
}
