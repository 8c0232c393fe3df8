#pragma once
// One entry point for every segmentation method, so tools and the node call the same code.

#include <memory>
#include <string>
#include <vector>

#include "symmetry_segmentation/scene.h"
#include "symmetry_segmentation/segmentation_config.h"
#include "symmetry_segmentation/segmentation_result.h"

namespace symmetry_segmentation {

class Segmenter {
 public:
  virtual ~Segmenter() = default;
  virtual std::string name() const = 0;
  /// Segments `scene`; indices refer to scene.cloud. Throws InputError on unusable input.
  virtual SegmentationResult segment(const Scene& scene) const = 0;
};

std::vector<std::string> availableMethods();
std::string defaultMethod();
/// Throws InputError for an unknown method name.
std::unique_ptr<Segmenter> makeSegmenter(const std::string& method, const SegmentationConfig& config);

}  // namespace symmetry_segmentation
