// Stage curve_pairs of the symmetry method: curve matching, plane mean shift and the hypotheses of
// boxes and cylinders.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>

#include "symmetry_segmentation/symmetry/normal_edge_curves.h"
#include "symmetry_segmentation/symmetry/symmetry_hypotheses.h"
#include "symmetry_segmentation/symmetry/symmetry_plane.h"
#include "test_clouds.h"

namespace ss = symmetry_segmentation;

namespace {

constexpr float kRad = static_cast<float>(M_PI) / 180.0f;

ss::SymmetryPlane makePlane(const Eigen::Vector3f& normal, const Eigen::Vector3f& through) {
  ss::SymmetryPlane plane;
  plane.normal = normal.normalized();
  plane.distance = -plane.normal.dot(through);
  return plane;
}

bool samePlane(const ss::SymmetryPlane& a, const ss::SymmetryPlane& b, float angle_deg, float distance) {
  return ss::planeAngleDeg(a, b) < angle_deg && ss::planeDistanceDifference(a, b) < distance;
}

bool containsPlane(const std::vector<ss::SymmetryHypothesis>& hypotheses, const ss::SymmetryPlane& plane,
                   float angle_deg = 3.0f, float distance = 0.01f) {
  return std::any_of(hypotheses.begin(), hypotheses.end(),
                     [&](const ss::SymmetryHypothesis& h) { return samePlane(h.plane, plane, angle_deg, distance); });
}

ss::PointT point(const Eigen::Vector3f& p, const Eigen::Vector3f& n) {
  ss::PointT q;
  q.getVector3fMap() = p;
  q.getNormalVector3fMap() = n;
  q.r = q.g = q.b = 200;
  return q;
}

/// A wiggly space curve appended to `cloud` as a Curve with analytic tangents, and its mirror
/// image in `mirror` (listed in the opposite order, to show order does not matter).
std::pair<ss::Curve, ss::Curve> mirroredCurves(ss::Cloud& cloud, const ss::SymmetryPlane& mirror) {
  ss::Curve a, b;
  std::vector<Eigen::Vector3f> positions, tangents;
  for (int k = 0; k < 25; ++k) {
    const float s = 0.01f * k;
    positions.emplace_back(0.06f + 0.02f * std::sin(20.0f * s), s, 0.05f + 0.3f * s * s);
    tangents.push_back(Eigen::Vector3f(0.4f * std::cos(20.0f * s), 1.0f, 0.6f * s).normalized());
  }
  for (std::size_t k = 0; k < positions.size(); ++k) {
    a.points.push_back(static_cast<int>(cloud.size()));
    a.tangents.push_back(tangents[k]);
    cloud.push_back(point(positions[k], Eigen::Vector3f::UnitZ()));
  }
  for (int k = static_cast<int>(positions.size()) - 1; k >= 0; --k) {
    b.points.push_back(static_cast<int>(cloud.size()));
    b.tangents.push_back(ss::reflectDirection(mirror, tangents[k]));
    cloud.push_back(point(ss::reflectPoint(mirror, positions[k]), Eigen::Vector3f::UnitZ()));
  }
  return {a, b};
}

/// addBox turned by `yaw` about the vertical through its base centre, then moved to `centre`.
ss::Cloud rotatedBox(const Eigen::Vector3f& size, float spacing, float yaw, const Eigen::Vector3f& centre) {
  ss::Cloud box;
  test_clouds::addBox(box, Eigen::Vector3f(-size.x() / 2, -size.y() / 2, 0.0f), size, spacing);
  const Eigen::Matrix3f rotation = Eigen::AngleAxisf(yaw, Eigen::Vector3f::UnitZ()).toRotationMatrix();
  for (auto& p : box.points) {
    p.getVector3fMap() = rotation * p.getVector3fMap() + centre;
    p.getNormalVector3fMap() = rotation * p.getNormalVector3fMap();
  }
  return box;
}

ss::Cloud cylinder(const Eigen::Vector3f& base, float radius, float height, float spacing) {
  ss::Cloud cloud;
  const int around = static_cast<int>(std::round(2.0f * static_cast<float>(M_PI) * radius / spacing));
  for (float z = spacing; z < height - 1e-6f; z += spacing) {
    for (int k = 0; k < around; ++k) {
      const float a = 2.0f * static_cast<float>(M_PI) * k / around;
      const Eigen::Vector3f n(std::cos(a), std::sin(a), 0.0f);
      cloud.push_back(point(base + radius * n + Eigen::Vector3f(0, 0, z), n));
    }
  }
  for (float x = -radius; x <= radius + 1e-6f; x += spacing) {
    for (float y = -radius; y <= radius + 1e-6f; y += spacing) {
      if (x * x + y * y <= radius * radius) {
        cloud.push_back(point(base + Eigen::Vector3f(x, y, height), Eigen::Vector3f::UnitZ()));
      }
    }
  }
  return cloud;
}

std::vector<ss::PlaneSample> noisyPlanes(const ss::SymmetryPlane& centre, int count, std::mt19937& random) {
  std::normal_distribution<float> angle(0.0f, 1.0f), offset(0.0f, 0.002f);
  std::vector<ss::PlaneSample> samples;
  for (int i = 0; i < count; ++i) {
    const Eigen::Vector3f axis = centre.normal.cross(Eigen::Vector3f::Random()).normalized();
    ss::PlaneSample s;
    s.plane.normal = Eigen::AngleAxisf(angle(random) * kRad, axis) * centre.normal;
    s.plane.distance = centre.distance + offset(random);
    if (i % 2 == 1) {  // Either sign describes the plane.
      s.plane.normal = -s.plane.normal;
      s.plane.distance = -s.plane.distance;
    }
    samples.push_back(s);
  }
  return samples;
}

}  // namespace

TEST(CurveMatching, MirrorImageCurvesGiveTheMirrorPlane) {
  const ss::SymmetryPlane mirror = makePlane({0.9f, 0.3f, 0.2f}, {0.0f, 0.05f, 0.05f});
  ss::Cloud cloud;
  const auto [a, b] = mirroredCurves(cloud, mirror);
  const ss::CurvePairParams params;
  const auto planes = ss::matchCurvePair(cloud, a, b, params);
  EXPECT_GE(planes.size(), 20u);
  for (const auto& sample : planes) {
    EXPECT_TRUE(samePlane(sample.plane, mirror, 0.5f, 0.001f))
        << sample.plane.normal.transpose() << " " << sample.plane.distance;
  }
}

TEST(CurveMatching, OneToOneAndTangentGated) {
  const ss::SymmetryPlane mirror = makePlane({1.0f, 0.0f, 0.0f}, Eigen::Vector3f::Zero());
  ss::Cloud cloud;
  auto [a, b] = mirroredCurves(cloud, mirror);
  const ss::CurvePairParams params;
  EXPECT_LE(ss::matchCurvePair(cloud, a, b, params).size(), a.points.size());
  // Turning each of b's tangents by 20 degrees breaks every mirror match.
  for (auto& t : b.tangents) t = Eigen::AngleAxisf(20.0f * kRad, t.cross(mirror.normal).normalized()) * t;
  for (const auto& sample : ss::matchCurvePair(cloud, a, b, params)) {
    EXPECT_FALSE(samePlane(sample.plane, mirror, 2.0f, 0.005f));
  }
}

TEST(CurveMatching, SymmetricCurveMatchesItself) {
  // A parabola in a vertical plane, symmetric about x = 0.05.
  ss::Cloud cloud;
  ss::Curve curve;
  for (int k = -12; k <= 12; ++k) {
    const float x = 0.01f * k;
    curve.points.push_back(static_cast<int>(cloud.size()));
    curve.tangents.push_back(Eigen::Vector3f(1.0f, 0.0f, 2.0f * 4.0f * x).normalized());
    cloud.push_back(point({0.05f + x, 0.1f, 0.1f + 4.0f * x * x}, Eigen::Vector3f::UnitY()));
  }
  const auto planes = ss::matchCurvePair(cloud, curve, curve, ss::CurvePairParams{});
  const ss::SymmetryPlane mirror = makePlane(Eigen::Vector3f::UnitX(), {0.05f, 0.0f, 0.0f});
  EXPECT_GE(planes.size(), 10u);
  EXPECT_LE(planes.size(), 12u) << "(i, j) and (j, i) are one match";
  for (const auto& sample : planes) EXPECT_TRUE(samePlane(sample.plane, mirror, 0.5f, 0.001f));
}

TEST(PlaneMeanShift, FindsBothPlanesStrongestFirstInAnyOrder) {
  std::mt19937 random(7);
  const ss::SymmetryPlane strong = makePlane({0.2f, 1.0f, 0.0f}, {0.3f, 0.1f, 0.0f});
  const ss::SymmetryPlane weak = makePlane({1.0f, -0.1f, 0.05f}, {-0.2f, 0.0f, 0.1f});
  auto samples = noisyPlanes(strong, 40, random);
  const auto weak_samples = noisyPlanes(weak, 20, random);
  samples.insert(samples.end(), weak_samples.begin(), weak_samples.end());
  std::uniform_real_distribution<float> uniform(-0.3f, 0.3f);
  for (int i = 0; i < 10; ++i) {  // Outliers anywhere.
    ss::PlaneSample s;
    s.plane = makePlane(Eigen::Vector3f::Random(), Eigen::Vector3f(uniform(random), uniform(random), uniform(random)));
    samples.push_back(s);
  }

  const auto modes = ss::meanShiftPlanes(samples, 5.0f, 0.01f);
  ASSERT_GE(modes.size(), 2u);
  EXPECT_TRUE(samePlane(modes[0].plane, strong, 1.0f, 0.002f));
  EXPECT_TRUE(samePlane(modes[1].plane, weak, 1.0f, 0.002f));
  EXPECT_NEAR(modes[0].support, 40, 2);
  EXPECT_NEAR(modes[1].support, 20, 2);
  for (const auto& m : modes) EXPECT_EQ(ss::canonicalPlane(m.plane).normal, m.plane.normal);

  std::shuffle(samples.begin(), samples.end(), random);
  const auto shuffled = ss::meanShiftPlanes(samples, 5.0f, 0.01f);
  ASSERT_EQ(shuffled.size(), modes.size());
  for (std::size_t m = 0; m < modes.size(); ++m) {
    EXPECT_EQ(shuffled[m].support, modes[m].support);
    EXPECT_EQ(shuffled[m].plane.normal, modes[m].plane.normal);
    EXPECT_EQ(shuffled[m].plane.distance, modes[m].plane.distance);
  }
}

TEST(PlaneMeanShift, PlanesThroughTheOriginAcrossTheSignFlip) {
  // Normals near +-y with a tiny x component flip sign under canonicalPlane: still one plane.
  std::vector<ss::PlaneSample> samples;
  for (int i = 0; i < 10; ++i) {
    ss::PlaneSample s;
    s.plane.normal = Eigen::Vector3f((i % 2 ? 1.0f : -1.0f) * 0.001f * i, 1.0f, 0.0f).normalized();
    s.plane.distance = 0.0005f * (i % 3);
    samples.push_back(s);
  }
  const auto modes = ss::meanShiftPlanes(samples, 5.0f, 0.01f);
  ASSERT_EQ(modes.size(), 1u);
  EXPECT_EQ(modes[0].support, 10);
  EXPECT_TRUE(ss::meanShiftPlanes({}, 5.0f, 0.01f).empty());
}

TEST(SymmetryHypotheses, RotatedBoxHasBothVerticalPlanes) {
  const float yaw = 25.0f * kRad;
  const Eigen::Vector3f centre(0.3f, -0.2f, 0.0f);
  const ss::CurvePairParams params;
  for (float spacing : {0.005f, 0.01f}) {
    const ss::Cloud cloud = rotatedBox({0.12f, 0.08f, 0.10f}, spacing, yaw, centre);
    const auto curves = ss::extractNormalEdgeCurves(cloud, ss::NormalEdgeCurveParams{});
    const auto hypotheses = ss::detectSymmetryHypotheses(cloud, curves, params);
    ASSERT_FALSE(hypotheses.empty());
    EXPECT_LE(static_cast<int>(hypotheses.size()), params.max_hypotheses);
    const Eigen::Vector3f x_axis(std::cos(yaw), std::sin(yaw), 0.0f);
    const Eigen::Vector3f y_axis(-std::sin(yaw), std::cos(yaw), 0.0f);
    EXPECT_TRUE(containsPlane(hypotheses, makePlane(x_axis, centre))) << "spacing " << spacing;
    EXPECT_TRUE(containsPlane(hypotheses, makePlane(y_axis, centre))) << "spacing " << spacing;
    for (std::size_t h = 1; h < hypotheses.size(); ++h) {
      EXPECT_GE(hypotheses[h - 1].support, hypotheses[h].support);
    }
    for (const auto& h : hypotheses) EXPECT_GE(h.support, params.min_plane_support);
  }
}

TEST(SymmetryHypotheses, CylinderHasAVerticalPlaneThroughItsAxis) {
  const Eigen::Vector3f base(-0.1f, 0.2f, 0.0f);
  const ss::Cloud cloud = cylinder(base, 0.04f, 0.12f, 0.005f);
  const ss::CurvePairParams params;
  const auto hypotheses = ss::detectSymmetryHypotheses(cloud, ss::extractNormalEdgeCurves(cloud, ss::NormalEdgeCurveParams{}), params);
  const bool found = std::any_of(hypotheses.begin(), hypotheses.end(), [&](const ss::SymmetryHypothesis& h) {
    return std::fabs(h.plane.normal.z()) < std::sin(3.0f * kRad) && std::fabs(ss::signedDistance(h.plane, base)) < 0.01f;
  });
  EXPECT_TRUE(found) << hypotheses.size() << " hypotheses";
}

TEST(SymmetryHypotheses, DeterministicAndEmptySafe) {
  const ss::Cloud cloud = rotatedBox({0.12f, 0.08f, 0.10f}, 0.01f, 0.3f, Eigen::Vector3f::Zero());
  const ss::CurvePairParams params;
  const auto curves = ss::extractNormalEdgeCurves(cloud, ss::NormalEdgeCurveParams{});
  const auto first = ss::detectSymmetryHypotheses(cloud, curves, params);
  const auto second = ss::detectSymmetryHypotheses(cloud, curves, params);
  ASSERT_EQ(first.size(), second.size());
  for (std::size_t h = 0; h < first.size(); ++h) {
    EXPECT_EQ(first[h].support, second[h].support);
    EXPECT_EQ(first[h].plane.normal, second[h].plane.normal);
  }
  EXPECT_TRUE(ss::detectSymmetryHypotheses(cloud, {}, params).empty());
}
