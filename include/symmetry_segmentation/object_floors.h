#pragma once
// The floor inside a hollow object, given back after segmentation.
//
// A bowl, a pot or a mug seen from above shows its inside bottom a few millimetres over the
// table, within the table margin: preprocessing drops it with the table, and in a single view
// that is a third of a bowl's points (segments at IoU 0.6). Its normal faces up like the
// table's, so object_bottoms' side test cannot tell it; where it lies can. Seen from above, the
// segment's points surround it: in each of 8 directions across the table a ray from it meets
// the segment's footprint (its points in sparse 1 cm cells left out: specks of the table's noise
// in a segment would close pockets anywhere). Table seen beside an object (an L's inner corner, between a U's legs,
// a box's turned footprint) has a way out. A pocket's outermost ring of cells is left to the
// table (under a bowl's overhanging rim the table is seen from the side), and so is a pocket
// smaller than min_floor_area. Pockets include the footprint's own cells (a floor's noise above
// the margin stays in the segment): where a solid object hides the table no view sees it, but
// table seen under an overhang wider than a cell (a lying bottle's side from low down) would
// count as floor; a handle's loop, joined to a mug's footprint, mostly falls in the ring.

#include <vector>

#include "symmetry_segmentation/preprocessing.h"
#include "symmetry_segmentation/scene.h"

namespace symmetry_segmentation {

/// Side of the footprint grid's cells (m), and the area (m^2) an enclosed pocket must have.
struct FloorParams {
  float cell = 0.01f;
  float min_floor_area = 0.0016f;
};

/// For each segment (sorted input indices): the input points preprocessing dropped within the
/// table margin (either side) that lie in a pocket of at least min_floor_area its footprint
/// encloses (its outermost cells left out), and are not in `taken` (sorted); sorted. A point
/// enclosed by two segments goes to the first. Empty without a table.
std::vector<std::vector<int>> enclosedFloors(const Scene& scene, const PreprocessedScene& prepared,
                                             const std::vector<std::vector<int>>& segments,
                                             const std::vector<int>& taken, const FloorParams& params);

}  // namespace symmetry_segmentation
