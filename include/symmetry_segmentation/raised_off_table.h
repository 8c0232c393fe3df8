#pragma once
// Whether a segment is raised off the table: the gap between the table margin and its base is
// wider than a few centimetres and than the segment is tall. What an object hides of itself from
// view (a ball's or a flared bowl's underside) is never taller than what is seen of it; a board
// hung over the table (a shelf) is seen from a height many times its own. Object floors and
// object_size's hanging test both ask it.

#include <optional>
#include <vector>

namespace symmetry_segmentation {

/// The base of a segment whose points' heights over the table are `heights` (reordered; not
/// empty): their 2nd percentile, a few strays of a neighbour aside.
float segmentBase(std::vector<float>& heights);

/// `heights`: the segment's points' heights over the table (reordered; values that are not
/// finite are dropped from it). Its base and top are
/// their 2nd and 98th percentiles (a few strays of a neighbour aside). The base when the gap
/// between `table_margin` and it is wider than `min_gap` and than top - base; else (and when
/// empty) none.
std::optional<float> raisedBase(std::vector<float>& heights, float table_margin, float min_gap);

}  // namespace symmetry_segmentation
