#pragma once
// A depth camera's noise grows with the square of range: past 1.3 m a RealSense table scatters
// 1-2 cm about its plane, and a fixed margin leaves a tenth of its far pixels above it - a sparse
// slab that joins every object on it into one. Each pixel is judged against the heights of the
// pixels around it, as the noise there is: one whose neighbourhood lies on the table and which
// is within that neighbourhood's own noise of it is the table. A board lying flat has its
// neighbourhood on top of it; a handle before the table stands out of the table's noise.

#include <cstdint>
#include <vector>

namespace symmetry_segmentation {

/// Per pixel of a `width` x `height` grid of heights above the table (row-major; NaN where the
/// pixel has no point): true where the height is above `margin` but is the table's noise - the
/// medians of the finite heights of its 3 x 3 neighbourhood and of the (2 `reach` + 1)^2 window
/// around it are within `margin`, and the pixel is within three robust sigmas of the window's
/// median (the sigma from the spread below the median: median minus lower quartile, as for a
/// Gaussian), three sigmas being more than `margin` (where they are not, the margin covers the
/// noise and decides).
/// Windows with fewer than half their pixels finite judge nothing.
std::vector<bool> tableNoisePixels(std::uint32_t width, std::uint32_t height, const std::vector<float>& heights,
                                   float margin, int reach);

}  // namespace symmetry_segmentation
