#pragma once
// Optional stage stray_color_pieces (our addition; out of the default list since 2026-12-02: it
// changed no figure on any data set once flat colour seams stopped splitting): along a crease
// where two objects touch, a cut may take a strip of the neighbour (the top of a shorter box
// in a row). After deduplication a small region of a segment coloured unlike the rest of it and
// like an adjacent segment moves there; print matches no neighbour and stays. Needs colour.
#include <vector>

#include "symmetry_segmentation/scene.h"
#include "symmetry_segmentation/symmetry/segment_filter.h"
#include "symmetry_segmentation/symmetry/stage.h"
#include "symmetry_segmentation/symmetry/symmetry_params.h"

namespace symmetry_segmentation {

/// Moves each small region of `segments` (`cloud`'s RGB; `neighbours[i]`: the working-cloud
/// points linked to point i) whose colour is unlike the rest of its segment and like that of an
/// adjacent segment (both mostly one colour) over to that segment. Returns how many points moved.
std::size_t moveStrayColorPieces(std::vector<CandidateSegment>& segments, const Cloud& cloud,
                                 const std::vector<std::vector<int>>& neighbours, const StrayColorParams& params);

/// The stage: moveStrayColorPieces on the segments.
class StrayColorStage : public Stage {
 public:
  explicit StrayColorStage(const StrayColorParams& params) : params_(params) {}
  void run(PipelineState& state) const override;

 private:
  StrayColorParams params_;
};

}  // namespace symmetry_segmentation
