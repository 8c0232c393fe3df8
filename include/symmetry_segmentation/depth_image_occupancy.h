#pragma once
// Free / occupied / unknown straight from one camera frame's depth, for single views without a
// map: a query point projects to a pixel; in front of what that pixel measured the ray passed
// through it (free), at the measured surface it is occupied, behind it, at a pixel with no
// return, or outside the image nothing is known. No ray casting and no octree: a 640x480 frame
// costs one pass over its pixels instead of a ray per point.
//
// The camera is fitted to the organized cloud itself (each pixel's point and that pixel give a
// direct linear transform), so no intrinsics or sensor pose are needed, and a frame already
// moved into a robot's base frame works as is.

#include <memory>
#include <optional>
#include <vector>

#include <Eigen/Core>

#include "symmetry_segmentation/occupancy.h"
#include "symmetry_segmentation/scene.h"

namespace symmetry_segmentation {

class DepthImageOccupancy {
 public:
  /// The occupancy of `frame` (organized: width x height pixels, NaN where nothing returned),
  /// or null when it is not one pinhole camera's image (unorganized, too few valid pixels, or
  /// its points do not reproject onto their pixels within a pixel) or the camera cannot be told
  /// from it (every point on one plane: a bare wall or table). A query within
  /// `surface_thickness` of the measured depth along its ray is on the surface (occupied).
  static std::shared_ptr<const DepthImageOccupancy> fromOrganizedCloud(const Cloud& frame, float surface_thickness);

  /// Const and thread-safe.
  Occupancy classify(const Eigen::Vector3f& point) const;

  /// The fitted camera's optical centre, in the cloud's frame.
  const Eigen::Vector3f& cameraCenter() const { return center_; }
  /// Root mean square distance (pixels) between the frame's points projected and their pixels.
  float reprojectionError() const { return reprojection_error_; }
  float surfaceThickness() const { return thickness_; }

 private:
  DepthImageOccupancy() = default;
  /// The pixel `point` projects to, or false when it is behind the camera or off the image.
  bool pixelOf(const Eigen::Vector3f& point, int& pixel) const;

  Eigen::Matrix<double, 3, 4> projection_ = Eigen::Matrix<double, 3, 4>::Zero();
  Eigen::Vector3f center_ = Eigen::Vector3f::Zero();
  int width_ = 0;
  int height_ = 0;
  std::vector<float> range_;  ///< Per pixel: distance from the centre to its point; NaN: no return.
  float thickness_ = 0.0f;
  float reprojection_error_ = 0.0f;
};

/// Where the camera of an organized frame was (its fitted optical centre, cloud frame), when
/// the frame is one pinhole camera's image: a camera frame is its own viewpoint.
std::optional<Eigen::Vector3f> cameraCenterOfFrame(const Cloud& frame);

}  // namespace symmetry_segmentation
