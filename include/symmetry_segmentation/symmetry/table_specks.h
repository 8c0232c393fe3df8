#pragma once
// Specks of the table's own noise carried by a segment. A depth camera leaves the table's points
// scattered a centimetre or two over the fitted plane; any vertical mirror plane maps that layer
// onto itself, and the cut's neighbour links (up to cut.max_neighbour_distance) chain specks to an
// object's foot. They are no part of the object: an L-shaped block 20 cm long carried specks
// 30 cm away in a RealSense frame, and its completed box grew to 53 cm.

#include <functional>
#include <vector>

#include "symmetry_segmentation/scene.h"
#include "symmetry_segmentation/table_surface.h"

namespace symmetry_segmentation {

/// `segment` (sorted indices into `cloud`) without its low pieces - pieces wholly within
/// `max_height` over `table`'s top (its plane oriented toward the objects) while another piece rises above
/// it - that `keep_low_piece` (given the piece's sorted indices; may be empty) does not keep. A
/// piece is the segment's points joined through `neighbours` links shorter than `max_link`. A
/// segment all of whose pieces are low comes back whole (the scrap test judges it as one), and
/// so does one with an index outside `cloud` or `neighbours`.
std::vector<int> withoutTableSpecks(const Cloud& cloud, const std::vector<std::vector<int>>& neighbours,
                                    const std::vector<int>& segment, const TableTop& table,
                                    float max_link, float max_height,
                                    const std::function<bool(const std::vector<int>&)>& keep_low_piece = {});

}  // namespace symmetry_segmentation
