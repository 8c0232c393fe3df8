#pragma once
// Stage 16, coaxial_pieces (our addition): a bowl, a pot or an open tin seen from the side
// and above shows its outer front wall and its inner back wall, and they meet only at the ends
// of the rim - its inside bottom lies within the table margin. Each wall is symmetric on its
// own, and the graph cut keeps one connected piece, so the object comes out as two segments
// (OSD learn37/38). What says they are one object is rotational symmetry: both walls turn
// about the same vertical axis. Two segments whose axes of revolution (fitted as the upright
// stage fits them) are within max_axis_distance, that share no point, span the same heights (over
// min_height_overlap of the shorter one) and come within max_gap of each other with no observed
// free space where they come closest, are joined when their union passes the filter under the
// plane of either; dedup then prefers the union (larger at equal smoothness). Two cans one
// behind the other have axes a diameter apart; a bowl turned over on a tin (OSD learn41) stands
// above it; a fruit lying in a bowl is seen across free space. A round body's handle is
// joined to it too (handle_pieces.h).
#include <optional>
#include <utility>
#include <vector>

#include <Eigen/Core>

#include "symmetry_segmentation/occupancy.h"
#include "symmetry_segmentation/scene.h"
#include "symmetry_segmentation/symmetry/stage.h"
#include "symmetry_segmentation/symmetry/symmetry_params.h"

namespace symmetry_segmentation {

/// The middle of the closest pair of points of `first` and `second` (indices into `cloud`), and
/// their distance (infinite when either is empty).
std::pair<Eigen::Vector3f, float> closestApproach(const Cloud& cloud, const std::vector<int>& first,
                                                  const std::vector<int>& second);

/// The heights along `up` (unit) that `points` (indices into `cloud`, not empty) span, 5 % of
/// them trimmed at either end.
std::pair<float, float> heightRange(const Cloud& cloud, const std::vector<int>& points, const Eigen::Vector3f& up);

/// How much of the shorter of two height ranges the other spans too, in [0, 1].
float rangeOverlap(const std::pair<float, float>& first, const std::pair<float, float>& second);

/// rangeOverlap of the height ranges of `first` and `second`; 0 if either is empty.
float heightOverlap(const Cloud& cloud, const std::vector<int>& first, const std::vector<int>& second,
                    const Eigen::Vector3f& up);

/// The vertical axis (a point on it) `points` turn about, if they are a surface of revolution:
/// the upright stage's axis of most of them, which `min_axis_share` of the side points' normal
/// lines pass (within axes.max_axis_residual).
std::optional<Eigen::Vector3f> revolutionAxis(const Cloud& cloud, const std::vector<int>& points,
                                              const Eigen::Vector3f& up, const UprightHypothesisParams& axes,
                                              float min_axis_share);

class CoaxialPieceStage : public Stage {
 public:
  CoaxialPieceStage(const CoaxialPieceParams& params, const UprightHypothesisParams& axes,
                    const SymmetryFilterParams& filter)
      : params_(params), axes_(axes), filter_(filter) {}
  void run(PipelineState& state) const override;

 private:
  CoaxialPieceParams params_;
  UprightHypothesisParams axes_;
  SymmetryFilterParams filter_;
};

}  // namespace symmetry_segmentation
