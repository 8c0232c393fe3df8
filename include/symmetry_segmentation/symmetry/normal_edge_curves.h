#pragma once
// Stage 1, curves (paper): supervoxels merged into smooth surfaces, and the curves
// along the normal edges where those surfaces meet, ordered, with a tangent per point. Curve
// pairs are where the method looks for symmetry planes; the surfaces also propose planes of
// their own (upright_hypotheses.h).

#include <vector>

#include <Eigen/Core>

#include "symmetry_segmentation/scene.h"
#include "symmetry_segmentation/symmetry/stage.h"
#include "symmetry_segmentation/symmetry/symmetry_params.h"

namespace symmetry_segmentation {

struct Curve {
  std::vector<int> points;                ///< Working-cloud indices, in order along the curve.
  std::vector<Eigen::Vector3f> tangents;  ///< Unit tangent per point (sign meaningless).
};

/// Merged-supervoxel label per working-cloud point (0 = unlabelled). Touching supervoxels merge
/// when their mean normals are within merge_normal_angle_deg, or when the normals where they
/// touch are and their mean normals are within 30 degrees (curved surfaces).
std::vector<int> mergedSegmentLabels(const Cloud& cloud, const NormalEdgeCurveParams& params);

/// Points with a neighbour of another merged segment within params.boundary_radius.
std::vector<int> boundaryPoints(const Cloud& cloud, const std::vector<int>& labels,
                                const NormalEdgeCurveParams& params);

/// Boundary points linked by a minimum spanning tree and split into disjoint ordered curves.
std::vector<Curve> linkCurves(const Cloud& cloud, const std::vector<int>& boundary,
                              const NormalEdgeCurveParams& params);

/// As above, linking only points of one merged segment: the boundary band of an edge has a
/// row on either side, and each row becomes its own clean curve instead of a zigzag.
std::vector<Curve> linkCurves(const Cloud& cloud, const std::vector<int>& boundary, const std::vector<int>& labels,
                              const NormalEdgeCurveParams& params);

/// Replaces the tangent of each curve point where two surfaces meet at an angle by their edge
/// direction (cross product of the two sides' mean normals near the point), which a coarse
/// voxel staircase does not disturb. Other points keep their along-curve tangent.
void useEdgeTangents(const Cloud& cloud, const std::vector<int>& labels, const NormalEdgeCurveParams& params,
                     std::vector<Curve>& curves);

/// All of stage 1 on a working cloud with normals (linkCurves with labels, then useEdgeTangents).
std::vector<Curve> extractNormalEdgeCurves(const Cloud& cloud, const NormalEdgeCurveParams& params);
/// As above, from merged-segment labels already computed (mergedSegmentLabels).
std::vector<Curve> extractNormalEdgeCurves(const Cloud& cloud, const std::vector<int>& labels,
                                           const NormalEdgeCurveParams& params);

/// The stage: the merged surfaces and their curves into the state.
class NormalEdgeCurveStage : public Stage {
 public:
  explicit NormalEdgeCurveStage(const NormalEdgeCurveParams& params) : params_(params) {}
  void run(PipelineState& state) const override;

 private:
  NormalEdgeCurveParams params_;
};

}  // namespace symmetry_segmentation
