// Fuzz target: a scene directory's scene_info.yaml, through loadScene. The directory also holds
// a valid one-point cloud.pcd, written once.
#include <algorithm>
#include <cctype>
#include <cmath>
#include <fstream>

#include "fuzz_support.h"
#include "symmetry_segmentation/errors.h"
#include "symmetry_segmentation/scene_io.h"

namespace ss = symmetry_segmentation;

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  static fuzz_support::ScratchFile info("scene_info.yaml");
  static const std::string cloud_path = [] {
    const std::string path = info.sibling("cloud.pcd");
    std::ofstream(path) << "VERSION 0.7\nFIELDS x y z\nSIZE 4 4 4\nTYPE F F F\nCOUNT 1 1 1\nWIDTH 1\nHEIGHT 1\n"
                           "VIEWPOINT 0 0 0 1 0 0 0\nPOINTS 1\nDATA ascii\n0.1 0.2 0.3\n";
    return path;
  }();
  info.write(data, size);
  ss::Scene scene;
  try {
    scene = ss::loadScene(info.directory());
  } catch (const ss::InputError&) {
    return 0;
  }
  FUZZ_CHECK(scene.cloud && scene.cloud->size() == 1);
  FUZZ_CHECK(scene.kind != "overall");
  FUZZ_CHECK(std::all_of(scene.kind.begin(), scene.kind.end(), [](char c) {
    return std::isalnum(static_cast<unsigned char>(c)) || c == '_' || c == '-';
  }));
  for (const auto& origin : scene.sensor_origins) FUZZ_CHECK(origin.allFinite());
  // Gravity, when given, is a finite unit vector (checkedUpDirection).
  if (scene.up) FUZZ_CHECK(scene.up->allFinite() && std::abs(scene.up->norm() - 1.0f) < 1e-4f);
  return 0;
}
