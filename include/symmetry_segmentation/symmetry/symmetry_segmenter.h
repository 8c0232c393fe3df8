#pragma once
// The symmetry method end to end: preprocessing, normal-edge curves, hypotheses, a graph cut
// per hypothesis, refinement, a second cut, scores, filtering and de-duplication.

#include "symmetry_segmentation/segmenter.h"

namespace symmetry_segmentation {

class SymmetrySegmenter : public Segmenter {
 public:
  SymmetrySegmenter(const PreprocessParams& preprocessing, const SymmetryParams& params)
      : preprocessing_(preprocessing), params_(params) {}
  std::string name() const override { return "symmetry"; }
  SegmentationResult segment(const Scene& scene) const override;

 private:
  PreprocessParams preprocessing_;
  SymmetryParams params_;
};

}  // namespace symmetry_segmentation
