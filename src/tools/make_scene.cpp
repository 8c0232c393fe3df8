// make_scene: writes a deterministic synthetic tabletop scene with ground truth.
//   make_scene --kind <kind> --seed N --output DIR [--views N] [--fusion-voxel M] [--image-scale K]
//              [--realistic] [--single-view kinect|realsense]
// Exit codes: 0 written, 1 generation or writing failed, 2 bad arguments.

#include <cerrno>
#include <cmath>
#include <chrono>
#include <cstdint>
#include <cstdlib>
#include <iostream>
#include <optional>
#include <set>
#include <string>

#include "symmetry_segmentation/errors.h"
#include "symmetry_segmentation/scene_io.h"
#include "symmetry_segmentation/synthetic/object_shapes.h"
#include "symmetry_segmentation/synthetic/scene_generator.h"

namespace {

using symmetry_segmentation::InputError;
namespace synthetic = symmetry_segmentation::synthetic;

constexpr int kExitFailure = 1;
constexpr int kExitUsage = 2;

const char* const kUsage =
    "usage: make_scene --kind <kind> --seed N --output DIR [--views N] [--fusion-voxel M]\n"
    "                  [--image-scale K] [--realistic] [--single-view SENSOR]\n"
    "       make_scene --list-kinds | --help\n"
    "Writes a synthetic tabletop scene (cloud.ply, occupancy.bt, table_plane.txt, labels.txt,\n"
    "scene_info.yaml) seen by a virtual depth camera from N poses (default 4) on a 60 degree arc,\n"
    "and each object's whole shape as ground truth for completion (objects.yaml: its box;\n"
    "objects_surface.ply: samples of every side but its base, 1 cm apart, with its label).\n"
    "The same kind and seed always give identical files.\n"
    "  --fusion-voxel M   voxel size (m) the views are fused with, 0.0005..0.05 (default 0.003);\n"
    "                     smaller gives more points\n"
    "  --image-scale K    camera resolution 640K x 480K, K in 1..6 (default 1), same field of view\n"
    "  --realistic        what real scenes have: a wall (sometimes a shelf) behind the table, the\n"
    "                     floor and clutter on it (all label 0), printed objects, books lying flat,\n"
    "                     balls and pots, shading\n"
    "  --single-view S    one organized frame of depth sensor S (kinect, realsense) in the camera's\n"
    "                     optical frame, as a single RGB-D camera gives it: cloud.pcd with NaN\n"
    "                     holes, no normals, no OctoMap, no table plane; labels per pixel\n";

struct Arguments {
  std::string kind;
  std::optional<uint32_t> seed;
  std::string output;
  int views = 4;
  double fusion_voxel = 0.003;
  int image_scale = 1;
  bool realistic = false;
  std::string single_view;  ///< Depth sensor name; empty = fused multi-view scene.
  bool help = false;
  bool list_kinds = false;
};

/// Whole-string finite decimal number.
std::optional<double> parseNumber(const std::string& text) {
  if (text.empty()) return std::nullopt;
  char* end = nullptr;
  errno = 0;
  const double value = std::strtod(text.c_str(), &end);
  if (errno != 0 || end != text.c_str() + text.size() || !std::isfinite(value)) return std::nullopt;
  return value;
}

/// Whole-string unsigned decimal in [0, max]; no sign, no trailing characters.
std::optional<unsigned long long> parseUnsigned(const std::string& text, unsigned long long max) {
  if (text.empty() || text.size() > 20) return std::nullopt;
  for (char c : text) {
    if (c < '0' || c > '9') return std::nullopt;
  }
  errno = 0;
  const unsigned long long value = std::strtoull(text.c_str(), nullptr, 10);
  if (errno != 0 || value > max) return std::nullopt;
  return value;
}

Arguments parseArguments(int argc, char** argv) {
  Arguments args;
  std::set<std::string> seen;
  for (int i = 1; i < argc; ++i) {
    const std::string flag = argv[i];
    if (flag == "--help" || flag == "-h") {
      args.help = true;
      continue;
    }
    if (flag == "--list-kinds") {
      args.list_kinds = true;
      continue;
    }
    if (flag == "--realistic") {
      args.realistic = true;
      continue;
    }
    if (flag != "--kind" && flag != "--seed" && flag != "--output" && flag != "--views" && flag != "--fusion-voxel" &&
        flag != "--image-scale" && flag != "--single-view") {
      throw InputError("unknown argument '" + flag + "'");
    }
    if (!seen.insert(flag).second) throw InputError(flag + " given twice");
    if (i + 1 >= argc) throw InputError(flag + " needs a value");
    const std::string value = argv[++i];
    if (flag == "--kind") {
      args.kind = value;
    } else if (flag == "--single-view") {
      args.single_view = value;
    } else if (flag == "--output") {
      if (value.empty()) throw InputError("--output needs a directory");
      args.output = value;
    } else if (flag == "--seed") {
      const auto seed = parseUnsigned(value, UINT32_MAX);
      if (!seed) throw InputError("--seed must be an integer in 0..4294967295, got '" + value + "'");
      args.seed = static_cast<uint32_t>(*seed);
    } else if (flag == "--fusion-voxel") {
      const auto voxel = parseNumber(value);
      if (!voxel || *voxel < 0.0005 || *voxel > 0.05) {
        throw InputError("--fusion-voxel must be a number in 0.0005..0.05, got '" + value + "'");
      }
      args.fusion_voxel = *voxel;
    } else if (flag == "--image-scale") {
      const auto scale = parseUnsigned(value, 6);
      if (!scale || *scale < 1) throw InputError("--image-scale must be an integer in 1..6, got '" + value + "'");
      args.image_scale = static_cast<int>(*scale);
    } else {
      const auto views = parseUnsigned(value, 16);
      if (!views || *views < 1) throw InputError("--views must be an integer in 1..16, got '" + value + "'");
      args.views = static_cast<int>(*views);
    }
  }
  if (!args.single_view.empty() && (seen.count("--views") || seen.count("--fusion-voxel"))) {
    throw InputError("--single-view is one unfused frame: --views and --fusion-voxel do not apply");
  }
  return args;
}

}  // namespace

int main(int argc, char** argv) {
  Arguments args;
  synthetic::GeneratorOptions options;
  try {
    args = parseArguments(argc, argv);
    if (args.help) {
      std::cout << kUsage;
      return 0;
    }
    if (args.list_kinds) {
      for (auto kind : synthetic::allSceneKinds()) std::cout << synthetic::toString(kind) << "\n";
      return 0;
    }
    if (args.kind.empty()) throw InputError("missing --kind (see --list-kinds)");
    if (!args.seed) throw InputError("missing --seed");
    if (args.output.empty()) throw InputError("missing --output");
    options.kind = synthetic::parseSceneKind(args.kind);
    options.seed = *args.seed;
    options.num_views = args.views;
    options.voxel_size = args.fusion_voxel;
    if (args.realistic) options.realism = synthetic::RealismOptions::realistic();
    if (!args.single_view.empty()) synthetic::useDepthSensor(options, args.single_view);
    // Same field of view at K times the resolution.
    const int k = args.image_scale;
    options.intrinsics.width *= k;
    options.intrinsics.height *= k;
    options.intrinsics.fx *= k;
    options.intrinsics.fy *= k;
    options.intrinsics.cx = 0.5 * (options.intrinsics.width - 1);
    options.intrinsics.cy = 0.5 * (options.intrinsics.height - 1);
    options.noise.disparity_focal_baseline *= k;  // disparity in pixels of the finer image
    synthetic::validate(options);
  } catch (const std::exception& e) {
    std::cerr << "make_scene: " << e.what() << " (try --help)\n";
    return kExitUsage;
  }

  try {
    const auto start = std::chrono::steady_clock::now();
    const synthetic::GeneratedScene generated = synthetic::generate(options);
    symmetry_segmentation::saveScene(generated.scene, args.output);
    synthetic::saveObjectShapes(generated.layout.world, generated.world_to_scene, args.output);
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    std::cout << "make_scene: " << generated.scene.name << ": " << generated.scene.size() << " points, "
              << generated.layout.world.objects.size() << " objects, " << options.num_views << " views, "
              << static_cast<int>(seconds * 1000.0 + 0.5) << " ms -> " << args.output << "\n";
    return 0;
  } catch (const std::exception& e) {
    std::cerr << "make_scene: " << e.what() << "\n";
    return kExitFailure;
  }
}
