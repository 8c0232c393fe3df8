#pragma once
// What rests on nothing is no tabletop object. A board hung over the table (a shelf) is
// mirror-symmetric like an object and passes every symmetry test; an object stands on the table
// or on another object. A segment rests on nothing when it is raised off the table (the gap
// under it wider than it is tall: raised_off_table.h) and no other point lies under its
// footprint within a few centimetres of its base (an object stacked on another has that
// object's sides under it).
// object_size drops such a segment when the table was also seen under it (a shelf), or the space
// under it was seen empty (a shelf shading all the table under it from a camera over the table's
// front: the camera still sees under its front edge, past it to the wall or the table beyond).
// The part of an object seen over another in front of it also rests on nothing in view, but
// the table under it is hidden, and so is the space under it (behind the occluder).

#include <optional>
#include <vector>

#include "symmetry_segmentation/scene.h"
#include "symmetry_segmentation/table_surface.h"

namespace symmetry_segmentation {

/// Whether `points` of `cloud` rest on nothing (see above): raised off the table's top by more than
/// three `cell`s over `table_margin`, and no other point of `cloud` one to five cells under their
/// base over their footprint (cells of side `cell`, grown by one). Indices out of range and points
/// that are not finite are left out.
bool restsOnNothing(const Cloud& cloud, const std::vector<int>& points, const TableTop& table,
                    float table_margin, float cell);

class OccupancyMap;

/// The share of probes straight under `points` of `cloud` - every 3 cm from 2 cm over
/// `table_margin` to 2 cm under their base (2nd percentile of their heights over the top)
/// - that `occupancy` classifies as free. None when there is no room for a probe.
std::optional<float> freeShareUnder(const Cloud& cloud, const std::vector<int>& points,
                                    const TableTop& table, float table_margin,
                                    const OccupancyMap& occupancy);

}  // namespace symmetry_segmentation
