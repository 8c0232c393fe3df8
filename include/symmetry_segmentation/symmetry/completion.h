#pragma once
// Stage 20, completion (beyond the paper): each object completed by its own symmetry. A grasp
// planner that gets only the visible half of a bottle plans against half a bottle; the plane we
// found says where the other half is. The reflection of a visible point that lands in space no
// view observed (unknown or occluded, not free, no observed point there, not under the table)
// is a point of the object's unseen side; reflections onto observed points add nothing new and
// reflections into free space are not the object. A surface of revolution seen from one side is
// mirrored onto itself by its planes through the viewer; copies of it turned about its axis
// that land in unobserved space are its back. Runs last: it changes no segment, it
// describes each one (reportedSegments turns it into the completed box and the symmetry frame).

#include <cstdint>
#include <functional>
#include <optional>
#include <unordered_set>
#include <vector>

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <pcl/kdtree/kdtree_flann.h>

#include "symmetry_segmentation/object_box.h"
#include "symmetry_segmentation/scene.h"
#include "symmetry_segmentation/segmentation_result.h"
#include "symmetry_segmentation/table_surface.h"
#include "symmetry_segmentation/symmetry/scene_evidence.h"
#include "symmetry_segmentation/symmetry/stage.h"
#include "symmetry_segmentation/symmetry/symmetry_params.h"

namespace symmetry_segmentation {

/// The reflections about `plane` of the working-cloud `points` that land where no view looked:
/// evidence.reflection() says Occluded (on no observed point, not in free space) and `hidden`
/// accepts the reflection (the stage: not free, no observed point within a voxel, not under the
/// table).
std::vector<Eigen::Vector3f> hiddenSideReflections(const SceneEvidence& evidence, const std::vector<int>& points,
                                                   const SymmetryPlane& plane,
                                                   const std::function<bool(const Eigen::Vector3f&)>& hidden);

/// What completion reflects: points with at least kMinSurfaceNeighbours others of their segment
/// closer than kSurfaceRadiusVoxels working voxels. On a 1 cm grid a point inside a surface has
/// 20 such neighbours, on its border about 12, inside a line of voxels (a rim, a handle) 4; a
/// stray voxel of mixed pixels 0-2. Reflected, stray voxels centimetres to decimetres off an
/// object stretched the completed box of single views (a u-shape's box IoU 0.77 -> 0.17).
constexpr float kSurfaceRadiusVoxels = 2.5f;
constexpr int kMinSurfaceNeighbours = 3;

/// The working-cloud `points` with at least `min_neighbours` others of `points` closer than `radius`
/// (`tree` indexes `cloud`): the object's surface, without the stray voxels a depth camera's mixed
/// pixels leave along its outline, centimetres off it, which the box leaves out as well.
std::vector<int> surfacePoints(const Cloud& cloud, const pcl::KdTreeFLANN<PointT>& tree, const std::vector<int>& points,
                               float radius, int min_neighbours);

/// The working-cloud `points` inside `visible` (the box the output gives the segment: objectBox
/// of its input points, which leaves out points in sparse cells) grown by `margin`. A segment can
/// take a sheet of the table's noise with it (a Kinect view: 148 of an L-block's 799 working
/// points, spread 40 cm around it just above the table margin); reflected, the sheet dragged the
/// completed box across the table (box IoU 0.92 -> 0.30). Only these points are completed.
std::vector<int> pointsInBox(const Cloud& cloud, const std::vector<int>& points, const ObjectBox& visible, float margin);

/// Whether `plane` passes within half the largest extent (segmentExtents) of the centroid of
/// `points` (indices into `cloud`). A flat object is mirror-symmetric about any plane across it,
/// one far beside it too, whose reflections land in space nobody saw, metres from the object; a
/// box seen face-on has its plane half its depth behind the face, and a depth up to its width
/// or height passes.
bool planeNearPoints(const Cloud& cloud, const std::vector<int>& points, const SymmetryPlane& plane,
                     const std::optional<Eigen::Vector3f>& up);

/// Copies of `points` turned about the axis through `axis_point` along `up` (unit) by k x 360 /
/// `steps` degrees, k = 1 .. steps - 1, that `hidden` accepts: a can seen from the front is
/// mirrored onto itself by its planes through the viewer, its back comes from turning it.
std::vector<Eigen::Vector3f> revolvedHiddenPoints(const std::vector<Eigen::Vector3f>& points,
                                                  const Eigen::Vector3f& axis_point, const Eigen::Vector3f& up,
                                                  int steps, const std::function<bool(const Eigen::Vector3f&)>& hidden);

/// The points of `points` (indices into `cloud`) on the surface of revolution about the vertical
/// axis through `axis_point` (`up` unit): side points whose normal line passes within
/// axes.max_axis_residual of the axis - not a mug's handle, not a lid. Empty when their median distance
/// from the axis is more than 0.6 of the widest horizontal extent of `points` (an axis fitted
/// through a neighbour's points, not one behind a surface seen from one side), or when they are
/// not round: their distances from the axis differ by more than 8 % (median) from the median at
/// their height (2 cm slices), or their normals do not turn continuously (coversAnArc; the
/// middles of a box's faces are round about its centre line).
std::vector<int> revolutionSurface(const Cloud& cloud, const std::vector<int>& points, const Eigen::Vector3f& axis_point,
                                   const Eigen::Vector3f& up, const UprightHypothesisParams& axes);

/// The axis through `axis_point` along `up` (unit) moved, in the horizontal plane, to where the
/// `surface` points are round about it: each 2 cm height slice the same distance from it (a
/// least-squares fit of the centre, each slice's radius the mean of its points'). The axis
/// coaxial_pieces fits from the points' normals is some millimetres to a centimetre off on a
/// camera's noisy normals, and the copies turned about it pass the far side by that much (a
/// can's completed box 0.96 to 0.85). A fit that moves it more than 2 cm is not taken.
Eigen::Vector3f refinedRevolutionAxis(const std::vector<Eigen::Vector3f>& surface, const Eigen::Vector3f& axis_point,
                                      const Eigen::Vector3f& up);

/// Of `surface`, the points whose distance from the axis (through `axis_point` along unit `up`)
/// is within 10 % of the median at their height (2 cm slices): noise and what is left of a handle
/// turned about the axis would widen the whole object.
std::vector<Eigen::Vector3f> roundPoints(const std::vector<Eigen::Vector3f>& surface, const Eigen::Vector3f& axis_point,
                                         const Eigen::Vector3f& up);

/// Where an object's side is seen only down to some height above the support (its foot behind
/// something in front of it), the side under each `cell`-wide column of `points` (indices into
/// `cloud`, with normals) whose lowest point faces sideways, carried straight down (along the
/// support plane's normal, oriented up) to the `support`'s top in `cell` steps - if `hidden`
/// accepts every step until within 1.5 cells of it. Objects stand on something: on the support,
/// or on what blocks the way down (seen, or free space: no column is added there).
std::vector<Eigen::Vector3f> groundedSidePoints(const Cloud& cloud, const std::vector<int>& points,
                                                const TableTop& support, float cell,
                                                const std::function<bool(const Eigen::Vector3f&)>& hidden);

/// `box` (its z along the support's up, as objectBox makes it) reaching down to the lowest of
/// `grounded` (groundedSidePoints) where that is lower: the box's other sides stay.
ObjectBox groundedBox(ObjectBox box, const std::vector<Eigen::Vector3f>& grounded);

/// `box` (its z along the support's up) of an object resting on the `support` (oriented up):
/// when its bottom is over the support's top by less than `reach`, it reaches down to it.
/// The table's cut takes an object's lowest centimetre or so with the table, and an object
/// standing there goes on down to it. The caller tells whether it stands on the support
/// (ObjectColumns::standsOn).
ObjectBox restingBox(ObjectBox box, const TableTop& support, float reach);

/// The `cell`-wide columns (across the support's up) that hold an object's points, for asking
/// whether it stands on another object: the columns are gathered once, then each other segment is
/// asked in turn. `cloud` must outlive it.
class ObjectColumns {
 public:
  /// The columns of `own` (indices into `cloud`) in `box`'s frame (its z along the support's up).
  ObjectColumns(const ObjectBox& box, const Cloud& cloud, const std::vector<int>& own, float cell);

  /// Whether `others` (indices into the same cloud) lie under the object: lower than `cell` over
  /// the box's bottom in a quarter or more of its columns. An object on a book or a board thinner
  /// than the resting reach stands on that, not on the table; a neighbour touching its side shares
  /// a few edge columns, and one in the empty corner of a can's box none.
  bool standsOn(const std::vector<int>& others) const;

 private:
  Eigen::Vector3f local(int index) const;
  std::int64_t column(const Eigen::Vector3f& local_point) const;

  ObjectBox box_;
  const Cloud& cloud_;
  float cell_;
  std::unordered_set<std::int64_t> columns_;
};

/// The first of `points` in each `cell`-sized cube, in order.
std::vector<Eigen::Vector3f> onePerCell(const std::vector<Eigen::Vector3f>& points, float cell);

/// The share of the added points left out at either end of each axis (stray reflections).
constexpr float kAddedPointsTrim = 0.025f;

/// The box of the completed object: turned as objectBox turns the visible points, bounded by
/// the visible box (objectBox: without stray points) and, where they pass it by more than a
/// working voxel (1 cm), by the added points less the `trim` share at either end of each axis
/// (a plane a few millimetres off throws its far reflections past the hidden side; the hidden
/// side itself is many points at one depth and stays). Only added points that continue the
/// object count, at least 3 of them: along each axis, outwards from the visible box up to the
/// first gap wider than 3 cm. A few added points farther out are reflections of strays the
/// visible box leaves out (a streak of table speckle given back with an object's bottom): one
/// box of a generated single view grew from 9 to 30 cm wide. On the development sets (generated
/// single Kinect views seeds 1-2 / 8-10, RealSense seeds 1-2, realistic seeds 11-14) mean completed
/// box IoU 0.743 / 0.734 / 0.541 / 0.757 to 0.755 / 0.744 / 0.584 / 0.761; completed boxes more
/// than 0.2 worse than the visible points' alone 9 to 2.
/// `noise`: the sensor's, for the visible box (objectBox).
ObjectBox completedBox(const std::vector<Eigen::Vector3f>& visible, const std::vector<Eigen::Vector3f>& added,
                       const std::optional<Eigen::Vector3f>& up, float trim = kAddedPointsTrim, float noise = 0.0f);

/// The object's symmetry frame: origin = `centroid` projected onto `plane`, x = the plane's
/// normal, z = `up` made orthogonal to x (any direction orthogonal to x when up is missing or
/// along it), y = z x x.
Eigen::Isometry3f symmetryFrame(const Eigen::Vector3f& centroid, const SymmetryPlane& plane,
                                const std::optional<Eigen::Vector3f>& up);

/// The stage: every segment's hidden-side reflections and, when it turns about a vertical axis,
/// its turned copies that land in unobserved space away from every observed point (one per
/// working voxel).
class CompletionStage : public Stage {
 public:
  CompletionStage(const CompletionParams& params, const UprightHypothesisParams& axes, float min_axis_share,
                  float voxel_size)
      : params_(params), axes_(axes), min_axis_share_(min_axis_share), voxel_size_(voxel_size) {}
  void run(PipelineState& state) const override;

 private:
  CompletionParams params_;
  UprightHypothesisParams axes_;
  float min_axis_share_;
  float voxel_size_;
};

}  // namespace symmetry_segmentation
