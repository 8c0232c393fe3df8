#pragma once
// Stage 15, color_seams (our addition): objects that meet flush, told apart by their colour.
// A box on a box of the same footprint, or boxes of one depth pushed into a row, are to the
// geometry one taller or wider box: no cut or crease test can part them, their colours can. A
// segment whose surface falls into a few large uniform-colour regions is split into them where
// the regions meet over flat faces along a seam running right across both, or at a concave
// crease between two sizeable regions (a bowl on a box); colour edges along an object's convex
// edges (a lid), around a narrow part (a bottle's cap) or in print keep it whole. Each part keeps
// the plane, of the segment's and those found on the part, that it contradicts least. Clouds
// without colour are left alone.
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
