#pragma once
// Stage 5e (our addition): strips of the next object's colour, moved to that object.
//
// Along a crease where two objects touch, a cut may take a strip of the neighbour (the top face
// of a shorter box in a row, which its plane mirrors into occluded space). After deduplication
// each object has its own segment; a small region of a segment whose colour is unlike the rest
// of that segment and like the adjacent segment's (both mostly one colour) belongs to that
// neighbour and moves there. Print on one object matches no neighbour and stays.
#include <vector>

#include "symmetry_segmentation/scene.h"
#include "symmetry_segmentation/symmetry/segment_filter.h"

namespace symmetry_segmentation {

/// Moves each small region of `segments` (`cloud`'s RGB; `neighbours[i]`: the working-cloud
/// points linked to point i) whose colour is unlike the rest of its segment and like that of an
/// adjacent segment (both mostly one colour) over to that segment. Colours closer than
/// `max_color_difference` (CIELAB, lightness at half weight) are alike. Returns how many points
/// moved.
std::size_t moveStrayColorPieces(std::vector<CandidateSegment>& segments, const Cloud& cloud,
                                 const std::vector<std::vector<int>>& neighbours, float max_color_difference = 15.0f);

}  // namespace symmetry_segmentation
