#pragma once
// Stage 3, upright (our addition): vertical planes proposed by single smooth surfaces, since
// objects stand on the table and a can or a bottle has almost no normal edges for curve pairs:
// the plane through a surface of revolution's axis that the scene contradicts least (a mug's
// goes through its handle), the bisector of a vertical face, the principal axes of a horizontal
// face. Needs the table; the cut, refine and filter judge these like any other hypothesis. The
// stage also adds the horizontal planes halfway up objects (mid_height_hypotheses.h).

#include <vector>

#include <Eigen/Core>

#include "symmetry_segmentation/scene.h"
#include "symmetry_segmentation/symmetry/scene_evidence.h"
#include "symmetry_segmentation/symmetry/stage.h"
#include "symmetry_segmentation/symmetry/surface_shapes.h"
#include "symmetry_segmentation/symmetry/symmetry_hypotheses.h"
#include "symmetry_segmentation/symmetry/symmetry_params.h"

namespace symmetry_segmentation {

/// A vertical axis of a surface of revolution.
struct VerticalAxis {
  std::vector<int> points;  ///< The surface points whose normal lines pass near it.
  Eigen::Vector3f point;    ///< On the axis, at the height of the points' centroid.
  float radius = 0.0f;      ///< Mean horizontal distance of the points from it.
};

/// The horizontal part of point i's normal, unit length, in `d`; false for a near-horizontal
/// surface point (normal within about 17 degrees of `up`), which shows no side to turn about an axis.
bool horizontalNormal(const Cloud& cloud, int i, const Eigen::Vector3f& up, Eigen::Vector3f& d);

/// Vertical axes of the surfaces of revolution `points` cover, most points first. Usually one;
/// where round objects touch, their sides meet with equal normals and merge into one surface,
/// and each object's axis is found by sampling pairs of normal lines (seeded: the same points
/// always give the same axes). `points` must be sorted.
std::vector<VerticalAxis> fitVerticalAxes(const Cloud& cloud, const std::vector<int>& points, const Eigen::Vector3f& up,
                                          const UprightHypothesisParams& params);

/// Whether the points' horizontal normal directions turn continuously: about the upright
/// min_normal_spread_deg of arc in steps of at most 10 degrees. Two flat faces meeting at an
/// edge (normals in two bundles) have normal lines that cross, yet no axis.
bool coversAnArc(const Cloud& cloud, const std::vector<int>& points, const Eigen::Vector3f& up,
                 const UprightHypothesisParams& params);

/// Planes proposed from each merged surface of `evidence.cloud()` (from surfaceShapes). `up` is
/// the unit normal of the supporting plane. Each hypothesis' support is its surface's size;
/// planes through an axis are anchored on the axis' surface. Deterministic, ordered by surface
/// label.
std::vector<SymmetryHypothesis> uprightHypotheses(const SceneEvidence& evidence, const std::vector<SurfaceShape>& surfaces,
                                                  const Eigen::Vector3f& up, const UprightHypothesisParams& params);

/// `extra` hypotheses appended to `base` unless near-equal (angle and offset) to one already there.
void appendDistinctHypotheses(std::vector<SymmetryHypothesis>& base, const std::vector<SymmetryHypothesis>& extra,
                              float max_angle_deg, float max_distance);

/// The stage: upright planes not near-equal to a hypothesis already there, appended; then the
/// horizontal planes halfway up (each anchored on its own face, so two at one height both stay).
/// `voxel_size`: the working voxel, how near a lower face must reach to be under or beside one.
class UprightStage : public Stage {
 public:
  UprightStage(const UprightHypothesisParams& params, float voxel_size) : params_(params), voxel_size_(voxel_size) {}
  void run(PipelineState& state) const override;

 private:
  UprightHypothesisParams params_;
  float voxel_size_;
};

}  // namespace symmetry_segmentation
