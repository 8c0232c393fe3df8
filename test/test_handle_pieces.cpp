// Stage coaxial_pieces, its handle part: a piece beside a surface of revolution that the vertical
// plane through the axis and the piece mirrors onto itself (a mug's handle) is joined to it on that
// plane; a piece that plane does not mirror onto itself, or one above the body, is not.
#include <gtest/gtest.h>

#include <cmath>
#include <numeric>

#include "fake_evidence.h"
#include "symmetry_segmentation/symmetry/handle_pieces.h"

namespace ss = symmetry_segmentation;

namespace {

constexpr float kStep = 0.005f;
const Eigen::Vector3f kUp = Eigen::Vector3f::UnitZ();

void addPoint(ss::Cloud& cloud, const Eigen::Vector3f& p) {
  ss::PointT q;
  q.getVector3fMap() = p;
  cloud.push_back(q);
}

/// A mug's body: the side of a vertical cylinder of radius 4 cm about the z axis, 10 cm tall.
ss::Cloud body() {
  ss::Cloud cloud;
  const int around = 50;
  for (int k = 0; k < around; ++k) {
    const float angle = 2.0f * static_cast<float>(M_PI) * static_cast<float>(k) / around;
    for (float z = 0.0f; z <= 0.1f + 1e-6f; z += kStep) addPoint(cloud, {0.04f * std::cos(angle), 0.04f * std::sin(angle), z});
  }
  return cloud;
}

/// A flat piece standing beside the body: centred `radial` out along the direction at `at`
/// (radians), running along the direction at `along` from `from` to `to` (m from its centre),
/// over the heights [bottom, top].
void addPiece(ss::Cloud& cloud, float at, float radial, float along, float from, float to, float bottom, float top) {
  const Eigen::Vector3f centre(radial * std::cos(at), radial * std::sin(at), 0.0f);
  const Eigen::Vector3f direction(std::cos(along), std::sin(along), 0.0f);
  for (float t = from; t <= to + 1e-6f; t += kStep) {
    for (float z = bottom; z <= top + 1e-6f; z += kStep) addPoint(cloud, centre + t * direction + z * kUp);
  }
}

/// Points closer than 1.5 steps are linked.
std::vector<std::vector<int>> linksOf(const ss::Cloud& cloud) {
  std::vector<std::vector<int>> links(cloud.size());
  for (std::size_t i = 0; i < cloud.size(); ++i) {
    for (std::size_t j = i + 1; j < cloud.size(); ++j) {
      if ((cloud[i].getVector3fMap() - cloud[j].getVector3fMap()).norm() < 1.5f * kStep) {
        links[i].push_back(static_cast<int>(j));
        links[j].push_back(static_cast<int>(i));
      }
    }
  }
  return links;
}

std::vector<int> firstPoints(std::size_t count) {
  std::vector<int> points(count);
  std::iota(points.begin(), points.end(), 0);
  return points;
}

/// bodiesWithHandles for the body (its first `body_points` points, plane x = 0) in `cloud`, the
/// whole cloud one island.
std::vector<ss::CandidateSegment> handlesOf(const ss::Cloud& cloud, std::size_t body_points) {
  test_support::FakeEvidence evidence(cloud, linksOf(cloud));
  evidence.landOnNearestWithin(0.3f * kStep);
  ss::CandidateSegment mug;
  mug.points = firstPoints(body_points);
  mug.plane.normal = Eigen::Vector3f::UnitX();
  mug.plane.distance = 0.0f;
  return ss::bodiesWithHandles(mug, Eigen::Vector3f::Zero(), firstPoints(cloud.size()), evidence, kUp, 0.3f);
}

}  // namespace

TEST(HandlePieces, AHandleIsJoinedOnThePlaneThroughTheAxisAndIt) {
  ss::Cloud cloud = body();
  const std::size_t body_points = cloud.size();
  const float at = static_cast<float>(M_PI) / 6.0f;  // 30 deg round from the body's plane
  addPiece(cloud, at, 0.055f, at, -0.01f, 0.01f, 0.02f, 0.08f);  // in the radial plane
  const auto joined = handlesOf(cloud, body_points);
  ASSERT_EQ(joined.size(), 1u);
  EXPECT_EQ(joined[0].points, firstPoints(cloud.size())) << "the body and all of the handle";
  const Eigen::Vector3f& normal = joined[0].plane.normal;
  EXPECT_NEAR(normal.dot(Eigen::Vector3f(std::cos(at), std::sin(at), 0.0f)), 0.0f, 1e-4f) << "through the handle";
  EXPECT_NEAR(normal.z(), 0.0f, 1e-4f) << "vertical";
  EXPECT_NEAR(joined[0].plane.distance, 0.0f, 1e-4f) << "through the axis";
}

TEST(HandlePieces, APieceThePlaneDoesNotMirrorOntoItselfIsNoHandle) {
  // The same piece turned 45 deg across the radial direction (a small box's face beside a can):
  // the plane through the axis and its middle mirrors it onto the other diagonal.
  ss::Cloud cloud = body();
  const std::size_t body_points = cloud.size();
  addPiece(cloud, 0.0f, 0.054f, static_cast<float>(M_PI) / 4.0f, -0.015f, 0.015f, 0.02f, 0.08f);
  EXPECT_TRUE(handlesOf(cloud, body_points).empty());
}

TEST(HandlePieces, APieceAboveTheBodyOrLargeAgainstItIsNoHandle) {
  // A radial piece that rises above the body's rim: something standing behind it, not its handle.
  ss::Cloud above = body();
  const std::size_t body_points = above.size();
  addPiece(above, 0.0f, 0.055f, 0.0f, -0.01f, 0.01f, 0.06f, 0.16f);
  EXPECT_TRUE(handlesOf(above, body_points).empty());
  // A radial piece a third of the body's size (over max_share 0.3): an object of its own.
  ss::Cloud large = body();
  addPiece(large, 0.0f, 0.085f, 0.0f, -0.04f, 0.04f, 0.0f, 0.1f);
  ASSERT_GT(large.size() - body_points, 0.3 * body_points);
  EXPECT_TRUE(handlesOf(large, body_points).empty());
  // Off: max_share 0.
  ss::Cloud cloud = body();
  addPiece(cloud, 0.0f, 0.055f, 0.0f, -0.01f, 0.01f, 0.02f, 0.08f);
  test_support::FakeEvidence evidence(cloud, linksOf(cloud));
  evidence.landOnNearestWithin(0.3f * kStep);
  ss::CandidateSegment mug;
  mug.points = firstPoints(body_points);
  EXPECT_TRUE(ss::bodiesWithHandles(mug, Eigen::Vector3f::Zero(), firstPoints(cloud.size()), evidence, kUp, 0.0f).empty());
  EXPECT_EQ(handlesOf(cloud, body_points).size(), 1u) << "and on again";
}
