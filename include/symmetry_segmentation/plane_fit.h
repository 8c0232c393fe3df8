#pragma once
// The largest plane of a cloud by RANSAC (PCL), refined by least squares over its inliers: the
// table estimate and the evaluation's plane through OSD's table-labelled points fit alike.

#include <optional>

#include <pcl/PointIndices.h>

#include "symmetry_segmentation/scene.h"

namespace symmetry_segmentation {

/// The plane (unit normal) with the most points of `cloud` within `distance` m, searched over
/// `iterations` RANSAC samples, and its inliers; none when the cloud has fewer than 3 points or
/// no plane is found.
std::optional<PlaneCoefficients> fitLargestPlane(const Cloud::ConstPtr& cloud, double distance, int iterations,
                                                 pcl::PointIndices& inliers);

}  // namespace symmetry_segmentation
