#pragma once
// A core SegmentationResult -> rviz markers: per object a translucent patch of its symmetry plane
// sized to the object, in the object's colour, an arrow along the plane normal, its completion
// (added points and box) and a text id.

#include <string>

#include <std_msgs/Header.h>
#include <visualization_msgs/MarkerArray.h>

#include "symmetry_segmentation/scene.h"
#include "symmetry_segmentation/segmentation_result.h"

namespace symmetry_segmentation {

/// First marker: DELETEALL (stale markers of the previous result vanish), then namespaces
/// "planes", "normals", "completions" (POINTS: the added points, the object's colour halfway to
/// white), "boxes" (translucent CUBE: the completed box, else the object's box) and "ids", with
/// marker id = object id (1-based). Segments without a symmetry plane get no plane or normal. Last (when the cloud has a usable point), namespace
/// "object_list", id 0: objectListText as one text centred 0.2 m above the cloud.
visualization_msgs::MarkerArray symmetryMarkers(const Cloud& cloud, const SegmentationResult& result,
                                                const std_msgs::Header& header);

/// "N objects", then one line per object: "id: P points[, occlusion O, smoothness S]" (P counts
/// the object's usable points, scores when the method gives them, 3 decimals).
std::string objectListText(const Cloud& cloud, const SegmentationResult& result);

}  // namespace symmetry_segmentation
