#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "symmetry_segmentation/plane_refinement.h"

namespace ss = symmetry_segmentation;

namespace {

constexpr float kDegree = static_cast<float>(M_PI) / 180.0f;

/// A table z = 0 seen from a camera at the origin's side: 1.2 m deep along y, its noise growing
/// with the square of the distance (sigma 3 mm at y = 0, 12 mm at the far edge), as a depth
/// camera's; one point every 1.5 cm (a coarse copy).
ss::Cloud tableWithGrowingNoise(std::mt19937& random) {
  ss::Cloud cloud;
  std::normal_distribution<float> unit(0.0f, 1.0f);
  for (float x = -0.5f; x <= 0.5f; x += 0.015f) {
    for (float y = 0.0f; y <= 1.2f; y += 0.015f) {
      const float range = 0.8f + y;
      ss::PointT p;
      p.x = x;
      p.y = y;
      p.z = 0.0047f * range * range * unit(random);
      cloud.push_back(p);
    }
  }
  return cloud;
}

/// The plane z = 0 tilted by `degrees` about the x axis (rising toward +y).
ss::PlaneCoefficients tilted(float degrees) {
  return ss::PlaneCoefficients(0.0f, -std::sin(degrees * kDegree), std::cos(degrees * kDegree), 0.0f);
}

float heightAt(const ss::PlaneCoefficients& plane, float y) {
  // The plane's z over (0, y): n_y y + n_z z + d = 0.
  return -(plane[1] * y + plane[3]) / plane[2];
}

}  // namespace

// A plane leaning half a degree over the far table, as RANSAC's refit within +-1 cm leaves it
// where the noise grows past 1 cm, comes back to the table: every square judged by its own noise.
TEST(PlaneRefinement, ATableLeaningWhereItsNoiseGrowsIsRefitToIt) {
  std::mt19937 random(7);
  const ss::Cloud table = tableWithGrowingNoise(random);
  const ss::PlaneCoefficients leaning = tilted(0.5f);
  ASSERT_GT(std::fabs(heightAt(leaning, 1.2f)), 0.009f);  // the case: a centimetre off at the far edge
  const ss::PlaneCoefficients refined = ss::refineToRegionalNoise(table, leaning, 0.03f, 0.2f);
  EXPECT_NEAR(heightAt(refined, 0.0f), 0.0f, 0.001f);
  EXPECT_NEAR(heightAt(refined, 1.2f), 0.0f, 0.002f);
  EXPECT_GT(refined.head<3>().dot(Eigen::Vector3f::UnitZ()), std::cos(0.1f * kDegree));
}

// A book lying on the table (1.3 cm) and the bottoms of things standing on it are within the
// band but out of their squares' noise: they do not lift the plane.
TEST(PlaneRefinement, ThingsOnTheTableDoNotLiftIt) {
  std::mt19937 random(8);
  ss::Cloud cloud = tableWithGrowingNoise(random);
  for (auto& p : cloud.points) {
    if (p.x > -0.2f && p.x < 0.1f && p.y > 0.1f && p.y < 0.4f) p.z += 0.013f;  // a book's top
  }
  const ss::PlaneCoefficients refined = ss::refineToRegionalNoise(cloud, tilted(0.0f), 0.03f, 0.2f);
  EXPECT_NEAR(heightAt(refined, 0.25f), 0.0f, 0.0015f);
  EXPECT_NEAR(heightAt(refined, 1.0f), 0.0f, 0.002f);
}

// Too few points near the plane, or points that pull it over by more than the allowed turn
// (a second surface crossing the band): the plane stays as it was.
TEST(PlaneRefinement, WithoutATableToFitThePlaneStays) {
  const ss::PlaneCoefficients start = tilted(1.0f);
  EXPECT_EQ(ss::refineToRegionalNoise(ss::Cloud(), start, 0.03f, 0.2f), start);
  std::mt19937 random(9);
  ss::Cloud steep;  // a surface 10 degrees off the start, all within its band near the origin
  for (float x = -0.1f; x <= 0.1f; x += 0.005f) {
    for (float y = -0.1f; y <= 0.1f; y += 0.005f) {
      ss::PointT p;
      p.x = x;
      p.y = y;
      p.z = std::tan(10.0f * kDegree) * x;
      steep.push_back(p);
    }
  }
  const ss::PlaneCoefficients flat = tilted(0.0f);
  EXPECT_EQ(ss::refineToRegionalNoise(steep, flat, 0.03f, 0.2f, 100, 3.0f), flat);
  // Allowed to turn that far, it does.
  const ss::PlaneCoefficients turned = ss::refineToRegionalNoise(steep, flat, 0.03f, 0.2f, 100, 20.0f);
  EXPECT_LT(turned.head<3>().dot(Eigen::Vector3f::UnitZ()), std::cos(5.0f * kDegree));
}
