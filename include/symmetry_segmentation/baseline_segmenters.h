#pragma once
// The methods robotics users run today, as baselines for the symmetry method:
// pcl::EuclideanClusterExtraction and pcl::LCCPSegmentation (the paper's baseline).

#include "symmetry_segmentation/segmenter.h"

namespace symmetry_segmentation {

class EuclideanSegmenter : public Segmenter {
 public:
  explicit EuclideanSegmenter(const SegmentationConfig& config)
      : preprocessing_(config.preprocessing), bottoms_(config.object_bottoms), params_(config.euclidean) {}
  std::string name() const override { return "euclidean"; }
  SegmentationResult segment(const Scene& scene) const override;

 private:
  PreprocessParams preprocessing_;
  ObjectBottomParams bottoms_;
  EuclideanParams params_;
};

class LccpSegmenter : public Segmenter {
 public:
  explicit LccpSegmenter(const SegmentationConfig& config)
      : preprocessing_(config.preprocessing), bottoms_(config.object_bottoms), params_(config.lccp) {}
  std::string name() const override { return "lccp"; }
  SegmentationResult segment(const Scene& scene) const override;

 private:
  PreprocessParams preprocessing_;
  ObjectBottomParams bottoms_;
  LccpParams params_;
};

}  // namespace symmetry_segmentation
