// Fuzz target: PCD cloud files through loadCloudFile (header check, then PCL's reader).
#include <algorithm>

#include <pcl/console/print.h>

#include "fuzz_support.h"
#include "symmetry_segmentation/errors.h"
#include "symmetry_segmentation/point_validity.h"
#include "symmetry_segmentation/scene_io.h"

namespace ss = symmetry_segmentation;

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  static fuzz_support::ScratchFile file("cloud.pcd");
  const std::string& path = file.write(data, size);
  ss::Scene scene;
  try {
    ss::loadCloudFile(path, scene);
  } catch (const ss::InputError&) {
    return 0;
  }
  FUZZ_CHECK(scene.cloud && !scene.cloud->empty());
  FUZZ_CHECK(static_cast<std::size_t>(scene.cloud->width) * scene.cloud->height == scene.cloud->size());
  FUZZ_CHECK(std::any_of(scene.cloud->begin(), scene.cloud->end(), ss::isUsablePoint));
  for (const auto& origin : scene.sensor_origins) FUZZ_CHECK(origin.allFinite());
  return 0;
}
