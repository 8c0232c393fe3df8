#pragma once
// Normals of a camera's organized frame from its pixel grid (pcl::IntegralImageNormalEstimation),
// at the sensor's own resolution. Estimated on the 1 cm working cloud instead, a normal averages
// a few centimetres of surface and a concave corner (a box standing on a box) turns smoothly
// over several voxels, where it should read as a crease.

#include <vector>

#include "symmetry_segmentation/scene.h"

namespace symmetry_segmentation {

/// The points of the organized `frame` (height > 1) that `indices` names, in that order, each
/// with the normal its pixel neighbourhood gives, oriented toward `viewpoint`, or NaN where it
/// gives none (depth jumps, the image's border). `smoothing_pixels`: the window's size in pixels
/// (PCL's depth-dependent growth adds only a tenth of a pixel per metre). Null when the frame is
/// not organized.
Cloud::Ptr pointsWithOrganizedNormals(const Cloud& frame, const std::vector<int>& indices,
                                      const Eigen::Vector3f& viewpoint, float smoothing_pixels);

}  // namespace symmetry_segmentation
