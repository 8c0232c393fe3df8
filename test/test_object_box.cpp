// Object boxes: standing on the support when its up is known, principal axes by extent when not.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>

#include <Eigen/Geometry>

#include "symmetry_segmentation/object_box.h"

namespace ss = symmetry_segmentation;

namespace {

ss::PointT point(const Eigen::Vector3f& p) {
  ss::PointT q;
  q.getVector3fMap() = p;
  return q;
}

/// The surface of a box with edges `size` along the columns of `frame`, centred on `center`,
/// sampled every `step` (5 mm by default), never its bottom; `with_top` false leaves its top (+z face) out, `all_sides`
/// false keeps only the -x and -y faces (a box seen from one corner).
ss::Cloud boxSurface(const Eigen::Vector3f& center, const Eigen::Matrix3f& frame, const Eigen::Vector3f& size,
                     bool with_top, bool all_sides, float step = 0.005f) {
  ss::Cloud cloud;
  const Eigen::Vector3f half = 0.5f * size;
  auto add = [&](const Eigen::Vector3f& local) { cloud.push_back(point(center + frame * local)); };
  for (float a = -half.x(); a <= half.x() + 1e-6f; a += step) {
    for (float b = -half.y(); b <= half.y() + 1e-6f; b += step) {
      if (with_top) add({a, b, half.z()});
    }
    for (float c = -half.z(); c <= half.z() + 1e-6f; c += step) {
      add({a, -half.y(), c});
      if (all_sides) add({a, half.y(), c});
    }
  }
  for (float b = -half.y(); b <= half.y() + 1e-6f; b += step) {
    for (float c = -half.z(); c <= half.z() + 1e-6f; c += step) {
      add({-half.x(), b, c});
      if (all_sides) add({half.x(), b, c});
    }
  }
  return cloud;
}

std::vector<int> allIndices(const ss::Cloud& cloud) {
  std::vector<int> all(cloud.size());
  for (std::size_t i = 0; i < all.size(); ++i) all[i] = static_cast<int>(i);
  return all;
}

bool parallel(const Eigen::Vector3f& a, const Eigen::Vector3f& b, float tolerance = 1e-3f) {
  return std::abs(std::abs(a.normalized().dot(b.normalized())) - 1.0f) < tolerance;
}

void expectRightHandedUnitAxes(const ss::ObjectBox& box) {
  EXPECT_TRUE((box.axes.transpose() * box.axes).isApprox(Eigen::Matrix3f::Identity(), 1e-4f));
  EXPECT_NEAR(box.axes.determinant(), 1.0f, 1e-4f);
}

}  // namespace

TEST(ObjectBox, StandsOnTheSupportAlongTheFootprintsSides) {
  // A 20 x 10 x 6 cm box on a tilted table, turned 30 degrees about the table's normal.
  const Eigen::Vector3f up = Eigen::Vector3f(0.0f, -0.6f, 0.8f);
  const Eigen::Matrix3f table = Eigen::Quaternionf::FromTwoVectors(Eigen::Vector3f::UnitZ(), up).toRotationMatrix();
  const Eigen::Matrix3f frame = table * Eigen::AngleAxisf(0.5236f, Eigen::Vector3f::UnitZ()).toRotationMatrix();
  const Eigen::Vector3f center(0.3f, -0.1f, 1.2f);
  const ss::Cloud cloud = boxSurface(center, frame, {0.2f, 0.1f, 0.06f}, true, true);
  const ss::ObjectBox box = ss::objectBox(cloud, allIndices(cloud), up);
  expectRightHandedUnitAxes(box);
  EXPECT_TRUE(parallel(box.axes.col(2), up));
  EXPECT_GT(box.axes.col(2).dot(up), 0.99f);  // z points up, not down
  EXPECT_TRUE(parallel(box.axes.col(0), frame.col(0)));  // x: the longer side
  EXPECT_TRUE(box.size.isApprox(Eigen::Vector3f(0.2f, 0.1f, 0.06f), 1e-3f)) << box.size.transpose();
  EXPECT_TRUE(box.center.isApprox(center, 1e-4f)) << box.center.transpose();
}

TEST(ObjectBox, AHalfSeenBoxStillStandsUpright) {
  // Two side faces seen from a corner, no top: the principal axes of these points lean, the box
  // on the support does not, and its height is the faces' height.
  const Eigen::Matrix3f frame = Eigen::AngleAxisf(0.3f, Eigen::Vector3f::UnitZ()).toRotationMatrix();
  const ss::Cloud cloud = boxSurface({0, 0, 0.05f}, frame, {0.16f, 0.08f, 0.1f}, false, false);
  const ss::ObjectBox upright = ss::objectBox(cloud, allIndices(cloud), Eigen::Vector3f::UnitZ());
  expectRightHandedUnitAxes(upright);
  EXPECT_TRUE(parallel(upright.axes.col(2), Eigen::Vector3f::UnitZ()));
  EXPECT_TRUE(parallel(upright.axes.col(0), frame.col(0)));
  EXPECT_TRUE(upright.size.isApprox(Eigen::Vector3f(0.16f, 0.08f, 0.1f), 1e-3f)) << upright.size.transpose();
  const ss::ObjectBox principal = ss::objectBox(cloud, allIndices(cloud), std::nullopt);
  EXPECT_FALSE(parallel(principal.axes.col(2), Eigen::Vector3f::UnitZ(), 0.05f) &&
               parallel(principal.axes.col(0), frame.col(0), 0.05f))
      << "the fixture should make the principal axes lean";
}

TEST(ObjectBox, WithoutUpTheAxesAreOrderedByExtent) {
  const Eigen::Matrix3f frame =
      (Eigen::AngleAxisf(0.4f, Eigen::Vector3f::UnitX()) * Eigen::AngleAxisf(0.7f, Eigen::Vector3f::UnitY())).toRotationMatrix();
  // Local extents 6, 20, 10 cm: the box's x must come out along the 20 cm edge, then 10, then 6.
  const ss::Cloud cloud = boxSurface({1, 2, 3}, frame, {0.06f, 0.2f, 0.1f}, true, true);
  const ss::ObjectBox box = ss::objectBox(cloud, allIndices(cloud), std::nullopt);
  expectRightHandedUnitAxes(box);
  EXPECT_TRUE(box.size.isApprox(Eigen::Vector3f(0.2f, 0.1f, 0.06f), 1e-3f)) << box.size.transpose();
  EXPECT_TRUE(parallel(box.axes.col(0), frame.col(1)));
  EXPECT_TRUE(parallel(box.axes.col(1), frame.col(2)));
  EXPECT_TRUE(box.center.isApprox(Eigen::Vector3f(1, 2, 3), 1e-4f));
}

TEST(ObjectBox, UnusablePointsAndBadIndicesAreLeftOut) {
  ss::Cloud cloud;
  cloud.push_back(point({0, 0, 0}));
  cloud.push_back(point({0.1f, 0.05f, 0.02f}));
  ss::PointT hole;
  hole.x = hole.y = hole.z = std::nanf("");
  cloud.push_back(hole);
  const ss::ObjectBox box = ss::objectBox(cloud, {0, 1, 2, 7, -1}, Eigen::Vector3f::UnitZ());
  EXPECT_TRUE(box.center.allFinite());
  EXPECT_NEAR(box.size.z(), 0.02f, 1e-6f);
  EXPECT_NEAR(box.size.head<2>().norm(), std::hypot(0.1f, 0.05f), 1e-5f);  // two points: a flat line
  const ss::ObjectBox empty = ss::objectBox(cloud, {2}, Eigen::Vector3f::UnitZ());
  EXPECT_EQ(empty.size, Eigen::Vector3f::Zero());
  EXPECT_EQ(empty.axes, Eigen::Matrix3f::Identity());
}

// A depth camera's stray pixels - mixed depths along an object's outline, in a thin streak
// behind it - must neither stretch the box nor turn its footprint.
TEST(ObjectBox, StrayPointsDoNotStretchTheBox) {
  const Eigen::Vector3f size(0.2f, 0.1f, 0.1f);
  ss::Cloud cloud = boxSurface({0, 0, 0.05f}, Eigen::Matrix3f::Identity(), size, true, true, 0.002f);
  const ss::ObjectBox clean = ss::objectBox(cloud, allIndices(cloud), Eigen::Vector3f::UnitZ());
  for (float t = 0.0f; t < 0.12f; t += 0.004f) cloud.push_back(point({0.1f + t, 0.03f + 0.5f * t, 0.08f}));
  const ss::ObjectBox box = ss::objectBox(cloud, allIndices(cloud), Eigen::Vector3f::UnitZ());
  EXPECT_TRUE(parallel(box.axes.col(0), Eigen::Vector3f::UnitX())) << box.axes;
  // Within a cell (1 cm) of the clean box: a stray point sharing a cell with the surface stays.
  EXPECT_NEAR(box.size.x(), size.x(), 0.01f);
  EXPECT_NEAR(box.size.y(), size.y(), 0.01f);
  EXPECT_NEAR(box.size.z(), size.z(), 0.01f);
  EXPECT_LT((box.center - clean.center).norm(), 0.01f) << box.center.transpose();
  // A sparse cloud (every cell about as sparse as the streak) keeps all of its points.
  ss::Cloud sparse = boxSurface({0, 0, 0.05f}, Eigen::Matrix3f::Identity(), size, true, true, 0.01f);
  sparse.push_back(point({0.2f, 0.0f, 0.05f}));
  const ss::ObjectBox kept = ss::objectBox(sparse, allIndices(sparse), Eigen::Vector3f::UnitZ());
  EXPECT_NEAR(kept.size.x(), 0.3f, 0.005f);
}

TEST(ObjectBox, AddObjectBoxesTakesTheSupportsUpElseTheScenes) {
  ss::Scene scene;
  auto cloud = std::make_shared<ss::Cloud>(boxSurface({0, 0, 0.05f}, Eigen::Matrix3f::Identity(), {0.2f, 0.1f, 0.1f}, true, true));
  scene.cloud = cloud;
  scene.up = Eigen::Vector3f::UnitX();  // the support, when there is one, wins over the scene's up
  ss::SegmentationResult result;
  ss::Segment segment;
  segment.indices = allIndices(*cloud);
  result.segments = {segment};
  ss::addObjectBoxes(scene, result);
  ASSERT_TRUE(result.segments[0].box.has_value());
  EXPECT_TRUE(parallel(result.segments[0].box->axes.col(2), Eigen::Vector3f::UnitX()));
  result.support = ss::SupportSurface{Eigen::Vector4f(0, 0, 2, 0), {}};  // unnormalised normal
  ss::addObjectBoxes(scene, result);
  EXPECT_TRUE(parallel(result.segments[0].box->axes.col(2), Eigen::Vector3f::UnitZ()));
  EXPECT_TRUE(result.segments[0].box->size.isApprox(Eigen::Vector3f(0.2f, 0.1f, 0.1f), 1e-3f));
}

namespace {

/// Deterministic, roughly Gaussian values (sum of 12 uniform draws), sigma `sigma`.
struct NoiseSource {
  std::uint32_t state = 777;
  float next(float sigma) {
    float sum = 0.0f;
    for (int k = 0; k < 12; ++k) {
      state = state * 1664525u + 1013904223u;
      sum += static_cast<float>(state >> 8) / 16777216.0f;
    }
    return sigma * (sum - 6.0f);
  }
};

}  // namespace

// A camera's depth noise spreads a board's faces to either side of them: the box of all the
// points is far too thick. With the sensor's noise given, each end comes in towards the board,
// never inside its true extent; and a real part sticking out (a handle) loses at most 2 sigma.
TEST(ObjectBox, TheSensorsNoiseDoesNotThickenTheBox) {
  const Eigen::Vector3f size(0.08f, 0.018f, 0.2f);
  const ss::Cloud clean = boxSurface({0, 0, 0.1f}, Eigen::Matrix3f::Identity(), size, true, true, 0.003f);
  constexpr float kSigma = 0.004f;
  ss::Cloud noisy;
  NoiseSource noise;
  for (const auto& p : clean.points) noisy.push_back(point(p.getVector3fMap() + Eigen::Vector3f(0, noise.next(kSigma), 0)));
  const ss::ObjectBox raw = ss::objectBox(noisy, allIndices(noisy), Eigen::Vector3f::UnitZ());
  const ss::ObjectBox pulled = ss::objectBox(noisy, allIndices(noisy), Eigen::Vector3f::UnitZ(), kSigma);
  EXPECT_GT(raw.size.y(), size.y() + 5.0f * kSigma) << "the noise widens the plain box";
  EXPECT_LT(pulled.size.y() - size.y(), 0.75f * (raw.size.y() - size.y())) << "a quarter of the widening goes";
  EXPECT_GT(pulled.size.y(), size.y());
  EXPECT_NEAR(pulled.size.x(), size.x(), 0.002f);
  EXPECT_NEAR(pulled.size.z(), size.z(), 0.002f);
  EXPECT_NEAR(pulled.center.y(), 0.0f, kSigma);
  // Either end gives up as many points: a cloud symmetric about x = 0 (two rows, one the
  // other's mirror image, no two points at one x) stays centred, at any size.
  for (int per_row : {40, 150}) {
    ss::Cloud mirrored;
    for (int i = 0; i < per_row; ++i) {
      const float x = -0.05f + 0.1f * static_cast<float>(i) / static_cast<float>(per_row - 1) + 0.0003f * std::sin(1.7f * i);
      mirrored.push_back(point({x, 0.0f, 0.05f}));
      mirrored.push_back(point({-x, 0.02f, 0.05f}));
    }
    const ss::ObjectBox centred = ss::objectBox(mirrored, allIndices(mirrored), Eigen::Vector3f::UnitZ(), 0.003f);
    EXPECT_NEAR(centred.center.x(), 0.0f, 3e-4f) << per_row << " points per row";
  }
  // No noise given: the box of the points, as before.
  EXPECT_TRUE(ss::objectBox(noisy, allIndices(noisy), Eigen::Vector3f::UnitZ(), 0.0f).size.isApprox(raw.size));

  // A block with a handle: 3 cm out along x, dense enough to be no stray, under 1 % of the points.
  ss::Cloud handled = boxSurface({0, 0, 0.05f}, Eigen::Matrix3f::Identity(), {0.2f, 0.1f, 0.1f}, true, true, 0.002f);
  const std::size_t block_points = handled.size();
  for (float t = 0.0f; t <= 0.03f + 1e-6f; t += 0.001f) {
    for (float z = 0.045f; z <= 0.055f + 1e-6f; z += 0.0025f) handled.push_back(point({0.1f + t, 0.0f, z}));
  }
  ASSERT_LT(handled.size() - block_points, block_points / 100);
  const float full = ss::objectBox(handled, allIndices(handled), Eigen::Vector3f::UnitZ()).size.x();
  ASSERT_NEAR(full, 0.23f, 0.002f);
  const float with_noise = ss::objectBox(handled, allIndices(handled), Eigen::Vector3f::UnitZ(), 0.002f).size.x();
  EXPECT_GE(with_noise, full - 2.0f * 0.002f - 1e-4f);
  EXPECT_LT(with_noise, full - 0.002f) << "the handle's last points do come in";
}

