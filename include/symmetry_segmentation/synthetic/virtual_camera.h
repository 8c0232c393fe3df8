#pragma once
// A Kinect-like virtual depth camera: pinhole projection, depth noise growing with the square
// of the range, and drop-outs where the surface is seen at a grazing angle.

#include <vector>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include "symmetry_segmentation/synthetic/random.h"
#include "symmetry_segmentation/synthetic/synthetic_world.h"

namespace symmetry_segmentation {
namespace synthetic {

struct CameraIntrinsics {
  int width = 640;
  int height = 480;
  double fx = 577.3;  ///< 58 degrees horizontal field of view at 640 pixels.
  double fy = 577.3;
  double cx = 319.5;
  double cy = 239.5;
};

struct DepthNoiseModel {
  double sigma_per_square_metre = 0.0017;  ///< Depth sigma = k * depth^2 (Kinect-like).
  double grazing_start_deg = 72.0;         ///< Incidence angle where drop-outs begin...
  double grazing_full_deg = 86.0;          ///< ...and where every pixel is lost.
  double min_depth = 0.4;
  double max_depth = 4.0;
  /// Structured light and active stereo measure disparity, not depth: with focal length x
  /// baseline (pixel metres) above 0, depth is rounded to the nearest disparity step, so
  /// steps grow with the square of the depth (Kinect: 577 px x 7.5 cm, 1/8 px).
  double disparity_focal_baseline = 0.0;
  double disparity_step = 0.125;  ///< Pixels.
  /// Projector (or second imager) this far along the camera's +x (m): surfaces it cannot
  /// see give no depth - the shadow beside every object's edge. 0 = none.
  double projector_baseline = 0.0;
};

/// Camera-to-world pose in the optical convention (x right, y down, z forward).
struct CameraPose {
  Eigen::Isometry3d camera_to_world = Eigen::Isometry3d::Identity();
  Eigen::Vector3d origin() const { return camera_to_world.translation(); }
};

/// Camera at `eye` looking at `target` with the world z axis up in the image.
CameraPose lookAt(const Eigen::Vector3d& eye, const Eigen::Vector3d& target);

struct ViewPoint {
  Eigen::Vector3f position;      ///< Measured: with depth noise.
  Eigen::Vector3f true_position; ///< Where the ray really met the surface.
  Eigen::Vector3f normal;  ///< True normal of the surface hit (unit, toward free space).
  int label = 0;
  Rgb color{{0, 0, 0}};
  int pixel = -1;  ///< Row-major index v * width + u.
};

struct RenderedView {
  Eigen::Vector3d origin;
  std::vector<ViewPoint> points;  ///< Row-major pixel order, drop-outs and misses left out.
};

/// Ray of pixel (u, v) in world coordinates; its direction has unit depth along the optical
/// axis, so the ray parameter t is the pixel's depth.
Ray pixelRay(const CameraPose& pose, const CameraIntrinsics& intrinsics, double u, double v);

/// Renders one depth image of `world` and back-projects it. Noise and drop-outs are drawn
/// from `random` in pixel order, so a given seed always yields the same view.
RenderedView renderView(const SyntheticWorld& world, const CameraPose& pose, const CameraIntrinsics& intrinsics,
                        const DepthNoiseModel& noise, Random& random);

/// Noise-free rendering (for tests and ground truth).
RenderedView renderViewExact(const SyntheticWorld& world, const CameraPose& pose,
                             const CameraIntrinsics& intrinsics);

}  // namespace synthetic
}  // namespace symmetry_segmentation
