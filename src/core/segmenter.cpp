#include "symmetry_segmentation/segmenter.h"

#include "symmetry_segmentation/baseline_segmenters.h"
#include "symmetry_segmentation/errors.h"

namespace symmetry_segmentation {

std::vector<std::string> availableMethods() { return {"euclidean", "lccp"}; }

// LCCP until the symmetry method lands: it is the stronger of the two baselines in clutter.
std::string defaultMethod() { return "lccp"; }

std::unique_ptr<Segmenter> makeSegmenter(const std::string& method, const SegmentationConfig& config) {
  if (method == "euclidean") return std::make_unique<EuclideanSegmenter>(config.preprocessing, config.euclidean);
  if (method == "lccp") return std::make_unique<LccpSegmenter>(config.preprocessing, config.lccp);
  std::string known;
  for (const auto& name : availableMethods()) known += (known.empty() ? "" : ", ") + name;
  throw InputError("unknown method '" + method + "' (available: " + known + ")");
}

}  // namespace symmetry_segmentation
