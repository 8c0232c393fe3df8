#include "symmetry_segmentation/synthetic/virtual_camera.h"

#include <algorithm>
#include <cmath>

namespace symmetry_segmentation {
namespace synthetic {
namespace {

RenderedView render(const SyntheticWorld& world, const CameraPose& pose, const CameraIntrinsics& intrinsics,
                    const DepthNoiseModel& noise, Random* random) {
  RenderedView view;
  view.origin = pose.origin();
  view.points.reserve(static_cast<std::size_t>(intrinsics.width) * intrinsics.height / 2);
  const double cos_start = std::cos(noise.grazing_start_deg * M_PI / 180.0);
  const double cos_full = std::cos(noise.grazing_full_deg * M_PI / 180.0);
  const Eigen::Vector3d projector = pose.camera_to_world * Eigen::Vector3d(noise.projector_baseline, 0.0, 0.0);
  for (int v = 0; v < intrinsics.height; ++v) {
    for (int u = 0; u < intrinsics.width; ++u) {
      const Ray ray = pixelRay(pose, intrinsics, u, v);
      const auto hit = rayIntersect(world, ray, noise.min_depth, noise.max_depth);
      if (!hit) continue;
      double depth = hit->t;
      if (random) {
        // Always draw both numbers so one pixel's fate never shifts the next pixel's noise.
        const double depth_noise = random->normal(0.0, noise.sigma_per_square_metre * depth * depth);
        const double drop_draw = random->uniform();
        const double cos_incidence = std::abs(hit->normal.dot(ray.direction.normalized()));
        // Drop-out probability rises linearly from 0 at grazing_start to 1 at grazing_full.
        const double drop_probability =
            std::clamp((cos_start - cos_incidence) / (cos_start - cos_full), 0.0, 1.0);
        if (drop_draw < drop_probability) continue;
        depth += depth_noise;
        if (noise.disparity_focal_baseline > 0.0 && noise.disparity_step > 0.0 && depth > 0.0) {
          const double steps = std::round(noise.disparity_focal_baseline / depth / noise.disparity_step);
          if (steps < 1.0) continue;  // beyond the last disparity step: no depth
          depth = noise.disparity_focal_baseline / (steps * noise.disparity_step);
        }
        if (noise.projector_baseline > 0.0) {
          const Ray light{projector, hit->point - projector};
          if (rayIntersect(world, light, 1e-6, 1.0 - 1e-5)) continue;  // in the projector's shadow
        }
      }
      ViewPoint point;
      point.position = ray.at(depth).cast<float>();
      point.true_position = hit->point.cast<float>();
      point.normal = hit->normal.cast<float>();
      point.label = hit->label;
      point.color = hit->color;
      point.pixel = v * intrinsics.width + u;
      view.points.push_back(point);
    }
  }
  return view;
}

}  // namespace

CameraPose lookAt(const Eigen::Vector3d& eye, const Eigen::Vector3d& target) {
  const Eigen::Vector3d forward = (target - eye).normalized();
  Eigen::Vector3d right = forward.cross(Eigen::Vector3d::UnitZ());
  if (right.norm() < 1e-9) right = Eigen::Vector3d::UnitX();  // looking straight down
  right.normalize();
  const Eigen::Vector3d down = forward.cross(right);
  CameraPose pose;
  pose.camera_to_world.linear().col(0) = right;
  pose.camera_to_world.linear().col(1) = down;
  pose.camera_to_world.linear().col(2) = forward;
  pose.camera_to_world.translation() = eye;
  return pose;
}

Ray pixelRay(const CameraPose& pose, const CameraIntrinsics& intrinsics, double u, double v) {
  const Eigen::Vector3d direction_camera((u - intrinsics.cx) / intrinsics.fx, (v - intrinsics.cy) / intrinsics.fy,
                                         1.0);
  Ray ray;
  ray.origin = pose.camera_to_world.translation();
  ray.direction = pose.camera_to_world.linear() * direction_camera;
  return ray;
}

RenderedView renderView(const SyntheticWorld& world, const CameraPose& pose, const CameraIntrinsics& intrinsics,
                        const DepthNoiseModel& noise, Random& random) {
  return render(world, pose, intrinsics, noise, &random);
}

RenderedView renderViewExact(const SyntheticWorld& world, const CameraPose& pose,
                             const CameraIntrinsics& intrinsics) {
  return render(world, pose, intrinsics, DepthNoiseModel{}, nullptr);
}

}  // namespace synthetic
}  // namespace symmetry_segmentation
