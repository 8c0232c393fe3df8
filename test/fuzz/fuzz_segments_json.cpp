// Fuzz target: segments.json (evaluate_segmentation --segments reads stored results) through
// readSegmentsJson.
#include <cmath>

#include "fuzz_support.h"
#include "symmetry_segmentation/errors.h"
#include "symmetry_segmentation/object_box.h"
#include "symmetry_segmentation/segments_json.h"

namespace ss = symmetry_segmentation;

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  static fuzz_support::ScratchFile file("segments.json");
  const std::string& path = file.write(data, size);
  ss::SegmentationResult result;
  try {
    result = ss::readSegmentsJson(path);
  } catch (const ss::InputError&) {
    return 0;
  }
  // Indices the evaluation can look up, planes and boxes the rest of the code can use.
  for (const ss::Segment& segment : result.segments) {
    for (int index : segment.indices) FUZZ_CHECK(index >= 0 && static_cast<std::size_t>(index) < result.input_points);
    if (segment.symmetry) FUZZ_CHECK(segment.symmetry->normal.allFinite() && std::isfinite(segment.symmetry->distance));
    if (segment.box) FUZZ_CHECK(ss::boxProblem(*segment.box).empty());
  }
  if (result.support) FUZZ_CHECK(result.support->plane.allFinite() && result.support->plane.head<3>().norm() > 0.0f);
  return 0;
}
