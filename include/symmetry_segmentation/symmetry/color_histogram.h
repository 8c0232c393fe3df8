#pragma once
// How much two point sets share their colours: the intersection of their coarse CIELAB
// histograms. A mean colour says little of print: the parts of one printed object (an L-shaped
// block's slab and upright) differ in mean by as much as two objects do, while the share of
// colours they have in common stays high (one print's palette over both); two objects share
// little.
#include <vector>

#include "symmetry_segmentation/scene.h"

namespace symmetry_segmentation {

/// The share (0..1) of colour that the points of `a` not in `b` and the points of `b` not in `a`
/// have in common (histogram intersection over CIELAB bins: lightness in steps of 10, a and b in
/// steps of 5). `a` and `b` sorted; 0 when either has no points of its own.
float colorOverlap(const Cloud& cloud, const std::vector<int>& a, const std::vector<int>& b);

}  // namespace symmetry_segmentation
