// Ray / surface-patch intersection on hand-computed cases, and footprint separation.

#include <gtest/gtest.h>

#include <cmath>

#include "symmetry_segmentation/synthetic/object_library.h"
#include "symmetry_segmentation/synthetic/surface_patch.h"
#include "symmetry_segmentation/synthetic/synthetic_object.h"

using namespace symmetry_segmentation::synthetic;

namespace {

Ray makeRay(const Eigen::Vector3d& origin, const Eigen::Vector3d& direction) { return Ray{origin, direction}; }

void expectVectorNear(const Eigen::Vector3d& actual, const Eigen::Vector3d& expected, double tolerance = 1e-9) {
  EXPECT_NEAR((actual - expected).norm(), 0.0, tolerance) << "actual " << actual.transpose() << ", expected "
                                                           << expected.transpose();
}

const BoxSolid kBox{Eigen::Vector3d(-1, -1, 0), Eigen::Vector3d(1, 1, 0.5)};

}  // namespace

TEST(SyntheticGeometry, BoxHitFromAboveGivesTopFaceAndUpNormal) {
  const auto hit = intersect(kBox, makeRay({0.2, 0.3, 1.0}, {0, 0, -1}), 0.0, 10.0);
  ASSERT_TRUE(hit);
  EXPECT_NEAR(hit->t, 0.5, 1e-12);
  expectVectorNear(hit->normal, {0, 0, 1});
}

TEST(SyntheticGeometry, BoxHitObliquelyEntersThroughTheSideFace) {
  // From (-3, 0, 0.25) toward +x and slightly up: enters x = -1 at t = 2 (z = 0.25 + 2 * 0.05).
  const auto hit = intersect(kBox, makeRay({-3, 0, 0.25}, {1, 0, 0.05}), 0.0, 10.0);
  ASSERT_TRUE(hit);
  EXPECT_NEAR(hit->t, 2.0, 1e-12);
  expectVectorNear(hit->normal, {-1, 0, 0});
}

TEST(SyntheticGeometry, BoxMissesBesideBehindAndBeyondRange) {
  EXPECT_FALSE(intersect(kBox, makeRay({-3, 1.5, 0.25}, {1, 0, 0}), 0.0, 10.0));  // passes beside
  EXPECT_FALSE(intersect(kBox, makeRay({3, 0, 0.25}, {1, 0, 0}), 0.0, 10.0));     // box is behind
  EXPECT_FALSE(intersect(kBox, makeRay({-3, 0, 0.25}, {1, 0, 0}), 0.0, 1.5));     // beyond t_max
}

TEST(SyntheticGeometry, CylinderSideHitAndNormal) {
  const CylinderSide side{0.5, 0.0, 1.0, true};
  // Off-centre by 0.3: the wall is at x = -sqrt(0.25 - 0.09) = -0.4.
  const auto hit = intersect(side, makeRay({-2, 0.3, 0.5}, {1, 0, 0}), 0.0, 10.0);
  ASSERT_TRUE(hit);
  EXPECT_NEAR(hit->t, 1.6, 1e-12);
  expectVectorNear(hit->normal, {-0.8, 0.6, 0.0});
  // Above the cylinder's height: no hit.
  EXPECT_FALSE(intersect(side, makeRay({-2, 0.0, 1.2}, {1, 0, 0}), 0.0, 10.0));
  // Inside wall of a cup, seen from the cavity: the far wall, normal toward the axis.
  const CylinderSide inner{0.5, 0.0, 1.0, false};
  const auto inner_hit = intersect(inner, makeRay({0, 0, 0.5}, {1, 0, 0}), 0.0, 10.0);
  ASSERT_TRUE(inner_hit);
  EXPECT_NEAR(inner_hit->t, 0.5, 1e-12);
  expectVectorNear(inner_hit->normal, {-1, 0, 0});
}

TEST(SyntheticGeometry, AnnulusHasAHole) {
  const Annulus ring{1.0, 0.3, 0.5, true};
  const auto hit = intersect(ring, makeRay({0.4, 0, 2}, {0, 0, -1}), 0.0, 10.0);
  ASSERT_TRUE(hit);
  EXPECT_NEAR(hit->t, 1.0, 1e-12);
  expectVectorNear(hit->normal, {0, 0, 1});
  EXPECT_FALSE(intersect(ring, makeRay({0.1, 0, 2}, {0, 0, -1}), 0.0, 10.0));
  EXPECT_FALSE(intersect(ring, makeRay({0.6, 0, 2}, {0, 0, -1}), 0.0, 10.0));
}

TEST(SyntheticGeometry, ConeSideNormalLeansUp) {
  const FrustumSide cone{0.0, 0.2, 0.1, 0.0};
  // At z = 0.1 the radius is 0.05; the slope of the side is -0.5, so the normal is (-1, 0, 0.5)/|.|.
  const auto hit = intersect(cone, makeRay({-1, 0, 0.1}, {1, 0, 0}), 0.0, 10.0);
  ASSERT_TRUE(hit);
  EXPECT_NEAR(hit->t, 0.95, 1e-12);
  expectVectorNear(hit->normal, Eigen::Vector3d(-1, 0, 0.5).normalized());
  // Above the apex the mirrored nappe must not be hit.
  EXPECT_FALSE(intersect(cone, makeRay({-1, 0, 0.3}, {1, 0, 0}), 0.0, 10.0));
}

TEST(SyntheticGeometry, BowlInnerSurfaceSeenFromAbove) {
  // Rim radius 0.1 at height 0.07, wall 0.006: inner sphere of radius 0.094 centred at z = 0.07.
  const SyntheticObject bowl = makeBowl(0.1, 0.07, 0.006);
  const auto hit = rayIntersect(bowl, makeRay({0.08, 0, 1}, {0, 0, -1}), 0.0, 10.0);
  ASSERT_TRUE(hit);
  const double z = 0.07 - std::sqrt(0.094 * 0.094 - 0.08 * 0.08);
  EXPECT_NEAR(hit->point.z(), z, 1e-9);
  // Inner surface: the normal points toward the centre of the sphere, i.e. into the bowl.
  expectVectorNear(hit->normal, (Eigen::Vector3d(0, 0, 0.07) - Eigen::Vector3d(0.08, 0, z)).normalized());
  EXPECT_GT(hit->normal.z(), 0.0);
  EXPECT_LT(hit->normal.x(), 0.0);
  // Straight down the middle: the flat inner floor.
  const auto floor_hit = rayIntersect(bowl, makeRay({0, 0, 1}, {0, 0, -1}), 0.0, 10.0);
  ASSERT_TRUE(floor_hit);
  EXPECT_NEAR(floor_hit->point.z(), 0.006, 1e-9);
  // On the rim ring.
  const auto rim_hit = rayIntersect(bowl, makeRay({0.097, 0, 1}, {0, 0, -1}), 0.0, 10.0);
  ASSERT_TRUE(rim_hit);
  EXPECT_NEAR(rim_hit->point.z(), 0.07, 1e-9);
  // From the side at mid-height: the outer surface, normal away from the centre.
  const auto outer_hit = rayIntersect(bowl, makeRay({-1, 0, 0.04}, {1, 0, 0}), 0.0, 10.0);
  ASSERT_TRUE(outer_hit);
  EXPECT_NEAR(outer_hit->point.x(), -std::sqrt(0.01 - 0.03 * 0.03), 1e-9);
  EXPECT_LT(outer_hit->normal.x(), 0.0);
  EXPECT_LT(outer_hit->normal.z(), 0.0);
}

TEST(SyntheticGeometry, MugFromAboveSeesTheInnerBottomAndTheHandle) {
  MugSize size;
  const SyntheticObject mug = makeMug(size);
  const auto bottom = rayIntersect(mug, makeRay({0.0, 0.0, 1.0}, {0, 0, -1}), 0.0, 10.0);
  ASSERT_TRUE(bottom);
  EXPECT_NEAR(bottom->point.z(), size.bottom, 1e-9);
  const double handle_x = size.radius + size.handle_reach - 0.5 * size.handle_thickness;
  const auto handle = rayIntersect(mug, makeRay({handle_x, 0.0, 1.0}, {0, 0, -1}), 0.0, 10.0);
  ASSERT_TRUE(handle);
  EXPECT_NEAR(handle->point.z(), 0.85 * size.height, 1e-9);
  // Beside the handle (off the mirror plane) the ray reaches nothing.
  EXPECT_FALSE(rayIntersect(mug, makeRay({handle_x, 0.05, 1.0}, {0, 0, -1}), 0.0, 10.0));
}

TEST(SyntheticGeometry, PosedObjectReturnsWorldPointAndNormal) {
  SyntheticObject box = makeBox(0.2, 0.1, 0.1);
  box.pose = uprightPose(1.0, 2.0, 0.0, M_PI / 2);  // local x now along world y
  // From world -x toward the box: meets the local -y face (half-depth 0.05) at x = 0.95.
  const auto hit = rayIntersect(box, makeRay({0, 2.0, 0.05}, {1, 0, 0}), 0.0, 10.0);
  ASSERT_TRUE(hit);
  expectVectorNear(hit->point, {0.95, 2.0, 0.05});
  expectVectorNear(hit->normal, {-1, 0, 0});
}

TEST(SyntheticGeometry, FootprintSeparation) {
  const Footprint square = convexHull({{0, 0}, {1, 0}, {1, 1}, {0, 1}, {0.5, 0.5}});
  ASSERT_EQ(square.size(), 4u);
  EXPECT_NEAR(separation(square, placeFootprint(square, {1.5, 0.0}, 0.0)), 0.5, 1e-12);
  EXPECT_LT(separation(square, placeFootprint(square, {0.5, 0.5}, 0.3)), 0.0);
  EXPECT_NEAR(separation(square, placeFootprint(square, {1.0, 0.0}, 0.0)), 0.0, 1e-12);  // flush
}
