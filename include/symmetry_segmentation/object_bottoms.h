#pragma once
// The bottom centimetre of each object, given back after segmentation.
//
// Preprocessing drops every point within the table margin (3 sigma of the table's noise, 5-15
// mm) so that no method mistakes the table for an object; with it goes the strip of each
// object's sides just above the table - 5-15 % of a small box, enough to push a correct segment
// under IoU 0.9. Normals tell the two apart: the table faces up, an object's sides face across
// it - the input's own, or for a camera frame without them, normals from its pixel grid as the
// working cloud got (a RealSense frame's bottom strip came back nowhere before: realistic
// single frames 0.675 -> 0.688). A hollow object's inside floor, which faces up like the
// table, comes back by where it lies: enclosed by the object's footprint (object_floors.h).
// The baselines call this on their final segments (their
// restore_object_bottoms); the symmetry method runs it as its stage object_bottoms.
#include <vector>

#include "symmetry_segmentation/object_floors.h"
#include "symmetry_segmentation/parameter_schema.h"
#include "symmetry_segmentation/preprocessing.h"
#include "symmetry_segmentation/scene.h"
#include "symmetry_segmentation/segmentation_result.h"

namespace symmetry_segmentation {

struct ObjectBottomParams {
  float max_side_normal_cos = 0.5f;
  float link_distance = 0.0f;
  float min_floor_area = 0.0016f;
};

inline void describeParameters(ParameterList<ObjectBottomParams>& list) {
  list.add("max_side_normal_cos", &ObjectBottomParams::max_side_normal_cos, 0.0, 1.0, "",
           "a dropped point whose normal has a smaller |cosine| with the table's is an object's side (0.5: 60 deg)")
      .add("link_distance", &ObjectBottomParams::link_distance, 0.0, 0.1, "m",
           "reach from a segment's point to a side point; 0: the working voxel size")
      .add("min_floor_area", &ObjectBottomParams::min_floor_area, 0.0, 1.0, "m^2",
           "dropped points in a pocket this large that a segment's footprint encloses are its floor (a bowl's inside); 0: none");
}

/// For each segment (sorted input-cloud indices): the input points preprocessing dropped as
/// within the table margin whose own normal runs across the table's and which are linked,
/// directly or through other such points, to the segment's points within the link distance and
/// lie under its lowest points (within the link distance of one, seen along the table's normal);
/// each goes to the segment of the nearest such point (none without input normals unless
/// `prepared` got the table band's from the frame's pixel grid); and those its footprint
/// encloses (object_floors.h, min_floor_area > 0); sorted. All empty without a table.
std::vector<std::vector<int>> objectBottoms(const Scene& scene, const PreprocessedScene& prepared, float voxel_size,
                                            const std::vector<std::vector<int>>& segments,
                                            const ObjectBottomParams& params);

/// Adds objectBottoms() to `segments`' indices (kept sorted). Returns how many were added.
std::size_t restoreObjectBottoms(const Scene& scene, const PreprocessedScene& prepared, float voxel_size,
                                 std::vector<Segment>& segments, const ObjectBottomParams& params);

}  // namespace symmetry_segmentation
