#pragma once
// Stage 4: a better plane for a segment. The segment's reflection is aligned back onto the
// segment with point-to-plane ICP (one-to-one correspondences); each point and the aligned image
// of its reflection then define a plane sample, and mean shift picks the refined plane.

#include <vector>

#include "symmetry_segmentation/scene.h"
#include "symmetry_segmentation/segmentation_result.h"
#include "symmetry_segmentation/symmetry/symmetry_params.h"

namespace symmetry_segmentation {

/// The refined plane, or `plane` itself when the segment is too small or ICP fails.
SymmetryPlane refinePlane(const Cloud& cloud, const std::vector<int>& segment, const SymmetryPlane& plane,
                          const SymmetryRefinementParams& refinement, const SymmetryDetectionParams& detection);

}  // namespace symmetry_segmentation
