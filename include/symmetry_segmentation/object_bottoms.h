#pragma once
// The bottom centimetre of each object, given back after segmentation.
//
// Preprocessing drops every point within the table margin (3 sigma of the table's noise, 5-10
// mm) so that no method mistakes the table for an object; with it goes the strip of each
// object's sides just above the table - 5-15 % of a small box, enough to push a correct segment
// under IoU 0.9. The input's own normals tell the two apart: the table faces up, an object's
// sides face across it. Every method calls this on its final segments.
#include <vector>

#include "symmetry_segmentation/preprocessing.h"
#include "symmetry_segmentation/scene.h"
#include "symmetry_segmentation/segmentation_result.h"

namespace symmetry_segmentation {

struct ObjectBottomParams {
  float max_normal_cos = 0.5f;  ///< |n . table normal| below this: a side, not the table (60 deg).
  float link_distance = 0.0f;   ///< Reach from a segment's point; 0: the preprocessing voxel size.
};

/// Adds to `segments` the input points preprocessing dropped as within the table margin whose
/// own normal runs across the table's and which are linked, directly or through other such
/// points, to a segment's point within `link_distance` (each goes to the segment of the nearest
/// such point). Does nothing when `preprocessing.restore_object_bottoms` is off, without a table
/// or without input normals. Returns how many were added.
std::size_t restoreObjectBottoms(const Scene& scene, const PreprocessedScene& prepared,
                                 const PreprocessParams& preprocessing, std::vector<Segment>& segments,
                                 const ObjectBottomParams& params = {});

}  // namespace symmetry_segmentation
