#pragma once
// A plane found by RANSAC and refined over its inliers leans wherever its noise outgrows the
// inlier band: a single view's far table (RealSense: sigma 1-2 cm past 1.3 m) is cut off at
// +-1 cm around the first guess, which the least-squares refit then keeps. Tilted by half a
// degree, the plane lies a centimetre under the far table and its noise comes through as an
// "object" joining everything on it.

#include "symmetry_segmentation/scene.h"

namespace symmetry_segmentation {

/// `plane` refitted to the points of `cloud` near it, each region judged by its own noise: the
/// points within `band` m are binned into `cell` m squares on the plane; a point counts when
/// it is within three of its square's noise sigmas (median absolute deviation) of the plane,
/// weighted by that sigma's inverse square. A few rounds, each from the last plane. `plane` as
/// it was when fewer than `min_points` points count or the refit turns it by more than
/// `max_turn_deg` (then the points near it are not one flat surface). Sign kept.
PlaneCoefficients refineToRegionalNoise(const Cloud& cloud, const PlaneCoefficients& plane, float band, float cell,
                                        std::size_t min_points = 100, float max_turn_deg = 3.0f);

}  // namespace symmetry_segmentation
