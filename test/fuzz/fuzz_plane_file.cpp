// Fuzz target: table_plane.txt ("a b c d") through loadPlaneFile.
#include <cmath>

#include "fuzz_support.h"
#include "symmetry_segmentation/errors.h"
#include "symmetry_segmentation/point_validity.h"
#include "symmetry_segmentation/scene_io.h"

namespace ss = symmetry_segmentation;

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  static fuzz_support::ScratchFile file("table_plane.txt");
  const std::string& path = file.write(data, size);
  ss::PlaneCoefficients plane;
  try {
    plane = ss::loadPlaneFile(path);
  } catch (const ss::InputError&) {
    return 0;
  }
  // A unit normal and an offset the rest of the pipeline can use.
  FUZZ_CHECK(plane.allFinite());
  FUZZ_CHECK(std::fabs(plane.head<3>().norm() - 1.0f) < 1e-4f);
  FUZZ_CHECK(std::fabs(plane[3]) <= ss::kMaxUsableCoordinate);
  return 0;
}
