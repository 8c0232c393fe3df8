#pragma once
// The methods robotics users run today, as baselines for the symmetry method:
// pcl::EuclideanClusterExtraction and pcl::LCCPSegmentation (the paper's baseline).

#include "symmetry_segmentation/segmenter.h"

namespace symmetry_segmentation {

class EuclideanSegmenter : public Segmenter {
 public:
  EuclideanSegmenter(const PreprocessParams& preprocessing, const EuclideanParams& params)
      : preprocessing_(preprocessing), params_(params) {}
  std::string name() const override { return "euclidean"; }
  SegmentationResult segment(const Scene& scene) const override;

 private:
  PreprocessParams preprocessing_;
  EuclideanParams params_;
};

class LccpSegmenter : public Segmenter {
 public:
  LccpSegmenter(const PreprocessParams& preprocessing, const LccpParams& params)
      : preprocessing_(preprocessing), params_(params) {}
  std::string name() const override { return "lccp"; }
  SegmentationResult segment(const Scene& scene) const override;

 private:
  PreprocessParams preprocessing_;
  LccpParams params_;
};

}  // namespace symmetry_segmentation
