#pragma once
// Stage 15, color_seams (our addition): a box on a box of the same footprint, or a row of boxes
// of one depth, is to the geometry one bigger box; their colours can part them. A segment of a
// few large uniform-colour regions meeting over flat faces along a seam right across both (or at
// a concave crease between sizeable regions) is split into them; colour edges on convex edges (a
// lid), around a narrow part (a bottle's cap) or in print keep it whole. Needs colour.
#include <vector>

#include "symmetry_segmentation/symmetry/scene_evidence.h"
#include "symmetry_segmentation/symmetry/segment_filter.h"
#include "symmetry_segmentation/symmetry/stage.h"
#include "symmetry_segmentation/symmetry/symmetry_params.h"

namespace symmetry_segmentation {

/// Replaces each segment of `segments` that is several flush objects of different colours (the
/// evidence cloud's RGB) by those objects, each with the plane (the segment's, or that of a
/// segment of `found` covering a good share of it) it contradicts least, scored anew. Returns how
/// many were split.
std::size_t splitAtColorSeams(std::vector<CandidateSegment>& segments, const std::vector<CandidateSegment>& found,
                              const SceneEvidence& evidence, const ColorSeamParams& params);

/// The stage: splitAtColorSeams on the segments, planes from every candidate; part sizes and
/// flat links as the filter's min_segment_points and smooth_normal_angle_deg.
class ColorSeamStage : public Stage {
 public:
  ColorSeamStage(const ColorSeamParams& params, const SymmetryFilterParams& filter) : params_(params), filter_(filter) {}
  void run(PipelineState& state) const override;

 private:
  ColorSeamParams params_;
  SymmetryFilterParams filter_;
};

}  // namespace symmetry_segmentation
