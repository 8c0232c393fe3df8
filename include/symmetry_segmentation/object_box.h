#pragma once
// The box a grasp planner gets for each object: a tight box around its points that stands on
// the support (one axis along gravity), because grippers approach objects on a table from
// above or from the side, and a box tilted along the visible points' variance misleads both.

#include <optional>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "symmetry_segmentation/scene.h"
#include "symmetry_segmentation/segmentation_result.h"

namespace symmetry_segmentation {

/// The box around the usable points `indices` selects from `cloud`, in the cloud's frame, leaving
/// out stray points (those in 1 cm cells holding under a fifth of the typical point's cell count).
/// With `up` (unit, the support's normal or gravity's opposite): z = up, x and y the sides of a
/// rectangle around the footprint (the points projected along up) - of those within 15 % of the
/// smallest area, the one whose sides most points lie on -, x the longer;
/// size = (length along x, along y, height). Without: the points' principal axes, ordered by the
/// box's extent along them (x the longest). Right-handed; x's sign is arbitrary. An empty box
/// (zero size, identity axes) when no point is usable. With `noise` (the sensor's depth noise
/// sigma at the objects, m; the support's), each end of each axis is pulled in to the 1 %
/// quantile of the points along it, by at most 2 noise: noisy points spread past a face.
ObjectBox objectBox(const Cloud& cloud, const std::vector<int>& indices, const std::optional<Eigen::Vector3f>& up,
                    float noise = 0.0f);

/// What is wrong with `box` as a box ("" when nothing): a value not finite, a negative size,
/// axes that are not a rotation (unit, orthogonal, right-handed, within 1e-3). For readers of
/// boxes from files.
std::string boxProblem(const ObjectBox& box);

/// The unit normal of `result`'s support (pointing up), if it has one.
std::optional<Eigen::Vector3f> supportUp(const SegmentationResult& result);

/// The up direction boxes use for `result` of `scene`: the support's normal, else the scene's up.
std::optional<Eigen::Vector3f> boxUp(const Scene& scene, const SegmentationResult& result);

/// Gives every segment of `result` its box (objectBox with boxUp); every method ends with it.
void addObjectBoxes(const Scene& scene, SegmentationResult& result);

}  // namespace symmetry_segmentation
