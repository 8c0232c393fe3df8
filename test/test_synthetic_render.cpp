// The virtual depth camera on a single box seen from a known pose.

#include <gtest/gtest.h>

#include <cmath>

#include "symmetry_segmentation/synthetic/object_library.h"
#include "symmetry_segmentation/synthetic/virtual_camera.h"

using namespace symmetry_segmentation::synthetic;

namespace {

constexpr double kSizeX = 0.2;
constexpr double kSizeY = 0.1;
constexpr double kSizeZ = 0.15;

SyntheticWorld singleBoxWorld() {
  SyntheticWorld world;
  SyntheticObject box = makeBox(kSizeX, kSizeY, kSizeZ);
  box.label = 1;
  box.color = colorForLabel(1);
  world.objects.push_back(box);
  return world;
}

/// Distance from p to the nearest face plane of the box, within the face's extent.
double distanceToBoxSurface(const Eigen::Vector3f& p) {
  const Eigen::Vector3d half(kSizeX / 2, kSizeY / 2, kSizeZ / 2);
  const Eigen::Vector3d q = p.cast<double>() - Eigen::Vector3d(0, 0, kSizeZ / 2);
  if ((q.cwiseAbs() - half).maxCoeff() > 0.005) return 1e9;  // outside the box's extent
  return (half - q.cwiseAbs()).cwiseAbs().minCoeff();
}

const CameraPose kCamera = lookAt(Eigen::Vector3d(0.0, -0.7, 0.6), Eigen::Vector3d(0.0, 0.0, 0.07));

}  // namespace

TEST(SyntheticRender, CentrePixelLooksAtTheTarget) {
  const CameraIntrinsics intrinsics;
  const Ray ray = pixelRay(kCamera, intrinsics, intrinsics.cx, intrinsics.cy);
  const Eigen::Vector3d expected = (Eigen::Vector3d(0.0, 0.0, 0.07) - ray.origin).normalized();
  EXPECT_NEAR((ray.direction.normalized() - expected).norm(), 0.0, 1e-12);
  EXPECT_NEAR(ray.direction.dot(kCamera.camera_to_world.linear().col(2)), 1.0, 1e-12);  // t is depth
  // Image up is world up: the top row of the image looks higher than the bottom row.
  EXPECT_GT(pixelRay(kCamera, intrinsics, 320, 0).direction.normalized().z(),
            pixelRay(kCamera, intrinsics, 320, 479).direction.normalized().z());
}

TEST(SyntheticRender, ExactViewOfABoxLiesOnItsVisibleFaces) {
  const RenderedView view = renderViewExact(singleBoxWorld(), kCamera, CameraIntrinsics{});
  ASSERT_GT(view.points.size(), 5000u);
  int top = 0;
  int front = 0;
  for (const auto& p : view.points) {
    ASSERT_EQ(p.label, 1);
    EXPECT_LT(distanceToBoxSurface(p.position), 1e-5);
    // Normals face the camera and are axis aligned for a box.
    const Eigen::Vector3f to_camera = view.origin.cast<float>() - p.position;
    EXPECT_GT(p.normal.dot(to_camera), 0.0f);
    EXPECT_NEAR(p.normal.norm(), 1.0f, 1e-5f);
    if (p.normal.z() > 0.99f) ++top;
    if (p.normal.y() < -0.99f) ++front;
  }
  // The camera is in front (-y) and above: only the top and front faces are visible.
  EXPECT_EQ(top + front, static_cast<int>(view.points.size()));
  EXPECT_GT(top, 1000);
  EXPECT_GT(front, 1000);
}

TEST(SyntheticRender, NoisyViewStaysNearTheSurfaceAndIsSeeded) {
  const DepthNoiseModel noise;
  Random random_a(7);
  Random random_b(7);
  Random random_c(8);
  const SyntheticWorld world = singleBoxWorld();
  const RenderedView a = renderView(world, kCamera, CameraIntrinsics{}, noise, random_a);
  const RenderedView b = renderView(world, kCamera, CameraIntrinsics{}, noise, random_b);
  const RenderedView c = renderView(world, kCamera, CameraIntrinsics{}, noise, random_c);
  ASSERT_EQ(a.points.size(), b.points.size());
  double squared_error = 0.0;
  bool all_same = true;
  for (std::size_t i = 0; i < a.points.size(); ++i) {
    ASSERT_EQ(a.points[i].position, b.points[i].position);
    const double error = (a.points[i].position - a.points[i].true_position).norm();
    squared_error += error * error;
    EXPECT_LT(error, 0.02);
  }
  const double depth = (Eigen::Vector3d(0.0, -0.7, 0.6) - Eigen::Vector3d(0, 0, 0.1)).norm();
  const double rms = std::sqrt(squared_error / a.points.size());
  // sigma = k z^2 along the depth axis (a bit more along the oblique ray).
  EXPECT_GT(rms, 0.5 * noise.sigma_per_square_metre * depth * depth);
  EXPECT_LT(rms, 2.0 * noise.sigma_per_square_metre * depth * depth);
  for (std::size_t i = 0; i < std::min(a.points.size(), c.points.size()); ++i) {
    if (a.points[i].position != c.points[i].position) all_same = false;
  }
  EXPECT_FALSE(all_same);
}

TEST(SyntheticRender, GrazingSurfacesDropOut) {
  // A camera almost level with the top face sees it at ~82 degrees incidence: most pixels drop.
  const CameraPose low = lookAt(Eigen::Vector3d(0.0, -0.9, kSizeZ + 0.12), Eigen::Vector3d(0.0, 0.0, kSizeZ));
  const SyntheticWorld world = singleBoxWorld();
  const RenderedView exact = renderViewExact(world, low, CameraIntrinsics{});
  Random random(3);
  const RenderedView noisy = renderView(world, low, CameraIntrinsics{}, DepthNoiseModel{}, random);
  auto countTop = [](const RenderedView& view) {
    int n = 0;
    for (const auto& p : view.points) n += p.normal.z() > 0.99f ? 1 : 0;
    return n;
  };
  ASSERT_GT(countTop(exact), 500);
  EXPECT_LT(countTop(noisy), countTop(exact) / 2);
}
