#include "symmetry_segmentation/segmenter.h"

#include "symmetry_segmentation/baseline_segmenters.h"
#include "symmetry_segmentation/errors.h"
#include "symmetry_segmentation/symmetry/symmetry_segmenter.h"

namespace symmetry_segmentation {

std::vector<std::string> availableMethods() { return {"symmetry", "euclidean", "lccp"}; }

std::string defaultMethod() { return "symmetry"; }

std::unique_ptr<Segmenter> makeSegmenter(const std::string& method, const SegmentationConfig& config) {
  if (method == "euclidean") return std::make_unique<EuclideanSegmenter>(config);
  if (method == "lccp") return std::make_unique<LccpSegmenter>(config);
  if (method == "symmetry") return std::make_unique<SymmetrySegmenter>(config);
  std::string known;
  for (const auto& name : availableMethods()) known += (known.empty() ? "" : ", ") + name;
  throw InputError("unknown method '" + method + "' (available: " + known + ")");
}

}  // namespace symmetry_segmentation
