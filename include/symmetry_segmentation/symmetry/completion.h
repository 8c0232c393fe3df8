#pragma once
// Stage 20, completion (beyond the paper): each object completed by its own symmetry. A grasp
// planner that gets only the visible half of a bottle plans against half a bottle; the plane we
// found says where the other half is. The reflection of a visible point that lands in space no
// view observed (unknown or occluded, not free, no observed point there, not under the table)
// is a point of the object's unseen side; reflections onto observed points add nothing new and
// reflections into free space are not the object. Runs last: it changes no segment, it
// describes each one (reportedSegments turns it into the completed box and the symmetry frame).

#include <optional>
#include <vector>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include "symmetry_segmentation/object_box.h"
#include "symmetry_segmentation/scene.h"
#include "symmetry_segmentation/segmentation_result.h"
#include "symmetry_segmentation/symmetry/scene_evidence.h"
#include "symmetry_segmentation/symmetry/stage.h"

namespace symmetry_segmentation {

/// The reflections about `plane` of the working-cloud `points` that land in unobserved space
/// above `table` (when given): evidence.reflection() says Occluded and the reflection is not
/// below the table's top.
std::vector<Eigen::Vector3f> hiddenSideReflections(const SceneEvidence& evidence, const std::vector<int>& points,
                                                   const SymmetryPlane& plane,
                                                   const std::optional<PlaneCoefficients>& table);

/// The box of the completed object: turned as objectBox turns the visible points, bounded by
/// every visible point and by the added points less the `trim` share at either end of each axis
/// (a plane a few millimetres off throws its far reflections past the hidden side; the hidden
/// side itself is many points at one depth and stays).
ObjectBox completedBox(const std::vector<Eigen::Vector3f>& visible, const std::vector<Eigen::Vector3f>& added,
                       const std::optional<Eigen::Vector3f>& up, float trim = 0.025f);

/// The object's symmetry frame: origin = `centroid` projected onto `plane`, x = the plane's
/// normal, z = `up` made orthogonal to x (any direction orthogonal to x when up is missing or
/// along it), y = z x x.
Eigen::Isometry3f symmetryFrame(const Eigen::Vector3f& centroid, const SymmetryPlane& plane,
                                const std::optional<Eigen::Vector3f>& up);

/// The stage: every segment's hidden-side reflections.
class CompletionStage : public Stage {
 public:
  void run(PipelineState& state) const override;
};

}  // namespace symmetry_segmentation
