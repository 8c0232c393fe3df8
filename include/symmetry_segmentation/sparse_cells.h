#pragma once
// A depth camera's stray pixels among an object's points: mixed depths at its outline and
// speckle lie alone or in thin streaks, and one of them stretches the object's box by
// centimetres or its footprint over the table.

#include <vector>

#include <Eigen/Core>

namespace symmetry_segmentation {

/// `points` without those in sparse cells: a 1 cm cell is sparse when it holds fewer than a
/// fifth of the points the typical point's cell holds (the median over the points), which keeps
/// every surface a camera samples evenly. Order kept.
std::vector<Eigen::Vector3f> withoutSparseCells(const std::vector<Eigen::Vector3f>& points);

}  // namespace symmetry_segmentation
