#pragma once
// A core SegmentationResult -> the node's messages: the object list, the labelled cloud and,
// for a camera's organized cloud, the label image.

#include <optional>
#include <vector>

#include <Eigen/Geometry>
#include <geometry_msgs/TransformStamped.h>
#include <sensor_msgs/Image.h>
#include <sensor_msgs/PointCloud2.h>
#include <std_msgs/Header.h>

#include "symmetry_segmentation/SegmentedObjectArray.h"
#include "symmetry_segmentation/scene.h"
#include "symmetry_segmentation/segmentation_result.h"

namespace symmetry_segmentation {

/// One object per segment (ids 1..N in segment order); clouds, boxes (the segment's, else
/// objectBox up the support's normal) and completions in `cloud`'s frame.
SegmentedObjectArray objectsMessage(const Cloud& cloud, const SegmentationResult& result,
                                    const std_msgs::Header& header);

/// A tf frame "object_<id>" per object with points, child of the objects' frame at their stamp:
/// its symmetry frame when it has a completion, else its bounding box's pose.
std::vector<geometry_msgs::TransformStamped> objectFrames(const SegmentedObjectArray& objects);

/// Empties every object's cloud and completed cloud (headers stay): a reply small enough to print.
void removeClouds(SegmentedObjectArray& objects);

/// Every finite input point with x y z rgb label: label k (1-based) and segment k's colour for
/// points of segment k (the first segment holding a point wins), label 0 and grey for the rest.
/// An organized cloud keeps its layout (width x height, NaN where the camera saw nothing).
sensor_msgs::PointCloud2 labelledCloudMessage(const Cloud& cloud, const SegmentationResult& result,
                                              const std_msgs::Header& header);

/// For an organized cloud: a mono16 image of its width x height, pixel = label as in the
/// labelled cloud (0: no object; labels above 65535 saturate), aligned with the camera image the
/// cloud was made from, as UOIS-style nodes publish it. Nothing for an unorganized cloud.
std::optional<sensor_msgs::Image> labelImageMessage(const Cloud& cloud, const SegmentationResult& result,
                                                    const std_msgs::Header& header);

}  // namespace symmetry_segmentation
