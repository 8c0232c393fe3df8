#pragma once
// Stage 2b: symmetry planes proposed from single smooth surfaces under the gravity prior of a
// tabletop: objects stand on the table, so most of their symmetry planes are vertical. The curve
// matching of stage 2 needs a pair of normal edges; a bottle or a can offers almost none (its
// rim and a gentle shoulder), so it is proposed from its surfaces instead:
//  - a curved surface whose normals meet a common vertical axis (surface of revolution): a
//    vertical plane through that axis, the orientation (of 24) that the score callback rates
//    best over the column around the axis;
//  - a vertical flat face: the vertical plane bisecting it;
//  - a horizontal flat face: the vertical planes along its two principal axes.
// These are hypotheses only; the graph cut, refinement and filter judge them as any other.

#include <functional>
#include <vector>

#include <Eigen/Core>

#include "symmetry_segmentation/scene.h"
#include "symmetry_segmentation/symmetry/symmetry_hypotheses.h"

namespace symmetry_segmentation {

struct UprightHypothesisParams {
  int min_surface_points = 20;         ///< Smaller merged surfaces propose nothing.
  float flat_curvature = 0.02f;        ///< Surfaces with less PCA curvature propose face planes.
  float flat_normal_spread_deg = 10.0f;///< Surfaces whose normals spread more propose an axis plane.
  float face_tilt_deg = 20.0f;         ///< Faces within this of vertical / horizontal propose planes.
  float max_axis_residual = 0.01f;     ///< RMS distance of normal lines from the fitted axis (m).
  float max_axis_radius = 0.25f;       ///< Farther axes are not an object's (m).
  float min_normal_spread_deg = 20.0f; ///< Normals must turn around the axis to locate it: the mean of
                                       ///< the unit normals is shorter than cos(this / 2) (an evenly
                                       ///< sampled arc needs about 35 degrees for the default).
};

/// How well point `index` is explained by its reflection about `plane`: positive when it lands on
/// a matching point, negative when it lands in free space, 0 when nothing is known.
using ReflectionScore = std::function<float(int index, const SymmetryPlane& plane)>;

/// Scores a reflection +1 when it lands within 1 cm of a cloud point, else 0 (no free-space
/// knowledge). For callers without an occupancy map.
ReflectionScore landingScore(const Cloud& cloud);

/// Planes proposed from each merged surface (labels from mergedSegmentLabels; 0 = none). `up` is
/// the unit normal of the supporting plane; `score` picks the orientation of planes through an
/// axis (the mug's plane goes through its handle: other orientations mirror it into free space).
/// Each hypothesis' support is its surface's size. Deterministic, ordered by surface label.
std::vector<SymmetryHypothesis> uprightHypotheses(const Cloud& cloud, const std::vector<int>& labels,
                                                  const Eigen::Vector3f& up, const UprightHypothesisParams& params,
                                                  const ReflectionScore& score);

/// `extra` hypotheses appended to `base` unless near-equal (angle and offset) to one already there.
void appendDistinctHypotheses(std::vector<SymmetryHypothesis>& base, const std::vector<SymmetryHypothesis>& extra,
                              float max_angle_deg, float max_distance);

}  // namespace symmetry_segmentation
