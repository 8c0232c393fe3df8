#pragma once
// Stage 15, color_seams (our addition): objects of different colours that touch at a concave
// crease (a bowl on a box, a short box against a taller one) can be one segment to the cut;
// their colours part them. A segment of a few large uniform-colour regions meeting along such a
// crease is split into them; colour edges on convex edges (a lid) or in print keep it whole.
// Print is no uniform region: where the large regions leave much of the segment, the large
// linked stretches of the rest are parts too (a printed box against a plain one), parted from
// others at concave creases only. A part much smaller than the rest (a small box beside a large
// one, or a handle) counts only when it stands alone: mirrored onto itself by the segment's
// plane, and more than one flat face. Flat seams (flush boxes of one depth, a box on a box of
// its footprint) split only between uniform parts that each stand alone - at such a seam also
// about the part's own middle, halfway from the seam to its far end (the end box of a flush
// row), unless the segment's plane mirrors it onto the part across the seam (one object in two
// colours either side of its plane looks just like that). On real frames a flat
// colour seam is far more often one object printed in two colours (OSD learn: split at every
// flat seam, 12 of 45 frames lost an object and none gained one; split between parts that stand
// alone, none changes). Parts that share one print's palette (color_histogram.h, composites'
// min_color_overlap) are one object's at any seam. Needs colour.
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
/// flat links as the filter's min_segment_points and smooth_normal_angle_deg, the distance of a
/// point on a plane from the working voxel size, one print's share of colours as composites'.
class ColorSeamStage : public Stage {
 public:
  ColorSeamStage(const ColorSeamParams& params, const SymmetryFilterParams& filter, float voxel_size,
                 float min_color_overlap)
      : params_(params), filter_(filter), voxel_size_(voxel_size), min_color_overlap_(min_color_overlap) {}
  void run(PipelineState& state) const override;

 private:
  ColorSeamParams params_;
  SymmetryFilterParams filter_;
  float voxel_size_;
  float min_color_overlap_;
};

}  // namespace symmetry_segmentation
