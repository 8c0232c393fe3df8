#pragma once
// A core SegmentationResult -> rviz markers: per object a translucent patch of its symmetry plane
// sized to the object, in the object's colour, an arrow along the plane normal and a text id.

#include <std_msgs/Header.h>
#include <visualization_msgs/MarkerArray.h>

#include "symmetry_segmentation/scene.h"
#include "symmetry_segmentation/segmentation_result.h"

namespace symmetry_segmentation {

/// First marker: DELETEALL (stale markers of the previous result vanish), then namespaces
/// "planes", "normals" and "ids" with marker id = object id (1-based). Segments without a
/// symmetry plane get a text id only.
visualization_msgs::MarkerArray symmetryMarkers(const Cloud& cloud, const SegmentationResult& result,
                                                const std_msgs::Header& header);

}  // namespace symmetry_segmentation
