#pragma once
// Stage 17, object_size (our addition): only what a robot could grasp is an object. A plane
// is mirror-symmetric about every plane across it, so a wall, a table remnant or a shelf passes
// every symmetry test; what gives them away is their size. A segment larger than max_extent
// along any axis (height over the table, or its footprint's sides), or mostly one plane wider
// than max_plane_extent, is dropped; so is one whose top is less than min_top_height over the
// table (a scrap of the table's own depth noise, which a far single view leaves above the margin),
// unless it hides the table: under a book or a board lying flat no view sees the table, while
// the noise's scrap has the table seen all through it. Before any test, a segment's specks of
// that noise go (table_specks.h): pieces of it as low as a scrap, apart from the rest. Extents
// leave out 5 % of the points at either end: a few stray points of a neighbour do not make an
// object large. A segment that hangs over the table (hanging_segments.h) or rises from below it
// past its edge (rising_segments.h) goes too.

#include <cstdint>
#include <optional>
#include <unordered_set>
#include <utility>
#include <vector>

#include <Eigen/Core>

#include "symmetry_segmentation/scene.h"
#include "symmetry_segmentation/table_grid.h"
#include "symmetry_segmentation/table_surface.h"
#include "symmetry_segmentation/symmetry/stage.h"
#include "symmetry_segmentation/symmetry/symmetry_params.h"

namespace symmetry_segmentation {

/// Height over `table`'s top of the top of `points` (95th percentile of their heights; 0 when empty).
float topHeight(const Cloud& cloud, const std::vector<int>& points, const TableTop& table);

/// Where the table itself was seen: the cells (side `cell`, on a grid in the table's plane) over
/// which the input cloud has points within `band` of the table's top (either side).
class TableSightings {
 public:
  TableSightings(const Cloud& input, const TableTop& table, float band, float cell);
  /// The share of the inner cells of the footprint of `points` (cells whose 8 neighbours hold
  /// points too) in which the table was seen; none when the footprint has no inner cell.
  std::optional<float> seenShareUnder(const Cloud& cloud, const std::vector<int>& points) const;

 private:
  TableGrid grid_;
  std::unordered_set<std::int64_t> seen_;
};

/// The extents (m) of `points` of `cloud` along three axes, largest first: with `up`, the height
/// along it and the sides of the footprint (principal axes in the plane normal to it), else the
/// principal axes.
Eigen::Vector3f segmentExtents(const Cloud& cloud, const std::vector<int>& points, const std::optional<Eigen::Vector3f>& up);

/// The points of `points` within `distance` of their largest plane (RANSAC, PCL), unsorted.
std::vector<int> largestPlanePoints(const Cloud::ConstPtr& cloud, const std::vector<int>& points, float distance);

/// Points this close to a plane are on it: a face's noise at the working resolution (1.5 voxels).
inline float onPlaneDistance(float voxel_size) { return 1.5f * voxel_size; }

/// Whether `points` of `cloud` are a graspable object under `params` (see the header).
bool hasObjectSize(const Cloud::ConstPtr& cloud, const std::vector<int>& points, const std::optional<Eigen::Vector3f>& up,
                   const ObjectSizeParams& params, float plane_distance);

class ObjectSizeStage : public Stage {
 public:
  ObjectSizeStage(const ObjectSizeParams& params, float voxel_size) : params_(params), voxel_size_(voxel_size) {}
  void run(PipelineState& state) const override;

 private:
  ObjectSizeParams params_;
  float voxel_size_;
};

}  // namespace symmetry_segmentation
