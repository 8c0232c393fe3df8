// Fuzz target: ground-truth labels.txt through loadLabelsFile. The first byte is the point
// count the labels must match (0..63), the rest the file.
#include "fuzz_support.h"
#include "symmetry_segmentation/errors.h"
#include "symmetry_segmentation/scene_io.h"

namespace ss = symmetry_segmentation;

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  static fuzz_support::ScratchFile file("labels.txt");
  if (size == 0) return 0;
  const std::size_t expected = data[0] % 64;
  const std::string& path = file.write(data + 1, size - 1);
  std::vector<int> labels;
  try {
    labels = ss::loadLabelsFile(path, expected);
  } catch (const ss::InputError&) {
    return 0;
  }
  FUZZ_CHECK(labels.size() == expected);
  for (int label : labels) FUZZ_CHECK(label >= 0);
  return 0;
}
