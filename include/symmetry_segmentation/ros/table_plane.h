#pragma once
// The supporting (table) plane given to the node (~table_plane parameter or topic), checked and
// moved into the processing frame. ROS-free (Eigen only): unit-tested without a master.

#include <string>
#include <vector>

#include <Eigen/Geometry>

#include "symmetry_segmentation/scene.h"

namespace symmetry_segmentation {

/// The plane a x + b y + c z + d = 0 from [a, b, c, d], scaled so (a, b, c) has unit length.
/// Throws InputError naming the problem when there are not exactly 4 values, one is not finite,
/// or (a, b, c) is (nearly) zero.
Eigen::Vector4d planeFromCoefficients(const std::vector<double>& values);

/// A plane given in a source frame, in a target frame, where p_target = source_to_target *
/// p_source: planes transform with the inverse transpose, pi_target = T^-T pi_source, i.e.
/// n_target = R n_source and d_target = d_source - n_target . t. A unit normal stays unit.
Eigen::Vector4d transformPlane(const Eigen::Vector4d& plane, const Eigen::Isometry3d& source_to_target);

/// The plane as the core stores it (Scene::table_plane): float, unit normal.
PlaneCoefficients toPlaneCoefficients(const Eigen::Vector4d& plane);

}  // namespace symmetry_segmentation
