#pragma once
// Part of stage 3, upright: horizontal planes halfway up objects. An object standing on the
// table - a box, a can, any prism - is mirror-symmetric about the horizontal plane halfway up
// it: its top face maps onto its hidden bottom, its sides onto themselves. Whatever stands on it
// maps below the table, and whatever it stands on maps into the free space above it, so the cut
// parts it from both, where every vertical plane through a stack's common axis keeps the stack
// whole (a can on a box, a box on a wider box). A top face seen over a lower face beside it
// (the lower box's top around the upper box's foot) proposes the plane halfway between the two.

#include <vector>

#include "symmetry_segmentation/scene.h"
#include "symmetry_segmentation/symmetry/symmetry_hypotheses.h"
#include "symmetry_segmentation/symmetry/symmetry_params.h"
#include "symmetry_segmentation/symmetry/surface_shapes.h"
#include "symmetry_segmentation/table_surface.h"

namespace symmetry_segmentation {

/// For each flat horizontal merged surface of `cloud` (from surfaceShapes; flat and horizontal
/// as the upright parameters say) at least min_mid_height over the table's top: the horizontal
/// plane halfway between it and the table under it, and halfway between it and each lower such
/// surface (by at least min_mid_height) whose extent reaches within a working voxel `reach` of
/// its own. Anchored on the face, support its size; none when min_mid_height is 0.
/// Deterministic, ordered by surface label.
std::vector<SymmetryHypothesis> midHeightHypotheses(const Cloud& cloud, const std::vector<SurfaceShape>& surfaces,
                                                    const TableTop& table, const UprightHypothesisParams& params,
                                                    float reach);

}  // namespace symmetry_segmentation
