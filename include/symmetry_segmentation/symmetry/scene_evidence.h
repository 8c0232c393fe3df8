#pragma once
// What the scene says about a symmetry plane, asked by every stage after the graph is built:
// where the reflection of a point lands (on a scene point, in unobserved space, in free space),
// how a set of points scores as an object symmetric about a plane, whether the sensor saw through
// a place, and where surfaces meet at concave creases. One interface instead of a callback per question, so a stage's unit test can
// answer them all with a small fake (test/test_support.h), and the pipeline with the real scene.

#include <cmath>
#include <vector>

#include <Eigen/Core>

#include "symmetry_segmentation/scene.h"
#include "symmetry_segmentation/segmentation_result.h"
#include "symmetry_segmentation/symmetry/reflection_data_term.h"
#include "symmetry_segmentation/symmetry/smoothness_weight.h"

namespace symmetry_segmentation {

class SceneEvidence {
 public:
  virtual ~SceneEvidence() = default;
  /// The working cloud every index refers to.
  virtual const Cloud& cloud() const = 0;
  /// Points linked to each point (the smoothness graph: each link listed from both ends, sorted).
  virtual const std::vector<std::vector<int>>& neighbours() const = 0;
  /// Where the reflection of point `index` about `plane` lands (reflection_data_term.h).
  virtual ReflectionEvidence reflection(int index, const SymmetryPlane& plane) const = 0;
  /// Occlusion and smoothness scores of `points` (sorted) as one object symmetric about `plane`.
  virtual SegmentScores scores(const std::vector<int>& points, const SymmetryPlane& plane) const = 0;
  /// Whether the sensor saw through `point` (observed free space).
  virtual bool observedFree(const Eigen::Vector3f& point) const = 0;
  /// Whether the link (a, b) crosses a concave crease, normals more than `angle_deg` apart: where
  /// separate objects touch. From the cloud's points and normals.
  virtual bool concaveCrease(int a, int b, float angle_deg) const {
    const PointT& p = cloud()[a];
    const PointT& q = cloud()[b];
    const Eigen::Vector3f n_p = p.getNormalVector3fMap();
    const Eigen::Vector3f n_q = q.getNormalVector3fMap();
    return n_p.dot(n_q) < std::cos(angle_deg * static_cast<float>(M_PI) / 180.0f) &&
           !isConvexLink(p.getVector3fMap(), n_p, q.getVector3fMap(), n_q);
  }

  /// The scene point the reflection of `index` lands on, or -1.
  int match(int index, const SymmetryPlane& plane) const {
    const ReflectionEvidence evidence = reflection(index, plane);
    return evidence.landing == ReflectionLanding::OnPoint ? evidence.match : -1;
  }
};

}  // namespace symmetry_segmentation
