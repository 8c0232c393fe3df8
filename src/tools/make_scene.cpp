// make_scene: writes a deterministic synthetic tabletop scene with ground truth.
//   make_scene --kind <kind> --seed N --output DIR [--views N]
// Exit codes: 0 written, 1 generation or writing failed, 2 bad arguments.

#include <cerrno>
#include <chrono>
#include <cstdint>
#include <cstdlib>
#include <iostream>
#include <optional>
#include <set>
#include <string>

#include "symmetry_segmentation/errors.h"
#include "symmetry_segmentation/scene_io.h"
#include "symmetry_segmentation/synthetic/scene_generator.h"

namespace {

using symmetry_segmentation::InputError;
namespace synthetic = symmetry_segmentation::synthetic;

constexpr int kExitFailure = 1;
constexpr int kExitUsage = 2;

const char* const kUsage =
    "usage: make_scene --kind <kind> --seed N --output DIR [--views N]\n"
    "       make_scene --list-kinds | --help\n"
    "Writes a synthetic tabletop scene (cloud.ply, occupancy.bt, table_plane.txt, labels.txt,\n"
    "scene_info.yaml) seen by a virtual depth camera from N poses (default 4) on a 60 degree arc.\n"
    "The same kind and seed always give identical files.\n";

struct Arguments {
  std::string kind;
  std::optional<uint32_t> seed;
  std::string output;
  int views = 4;
  bool help = false;
  bool list_kinds = false;
};

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
    if (flag != "--kind" && flag != "--seed" && flag != "--output" && flag != "--views") {
      throw InputError("unknown argument '" + flag + "'");
    }
    if (!seen.insert(flag).second) throw InputError(flag + " given twice");
    if (i + 1 >= argc) throw InputError(flag + " needs a value");
    const std::string value = argv[++i];
    if (flag == "--kind") {
      args.kind = value;
    } else if (flag == "--output") {
      if (value.empty()) throw InputError("--output needs a directory");
      args.output = value;
    } else if (flag == "--seed") {
      const auto seed = parseUnsigned(value, UINT32_MAX);
      if (!seed) throw InputError("--seed must be an integer in 0..4294967295, got '" + value + "'");
      args.seed = static_cast<uint32_t>(*seed);
    } else {
      const auto views = parseUnsigned(value, 16);
      if (!views || *views < 1) throw InputError("--views must be an integer in 1..16, got '" + value + "'");
      args.views = static_cast<int>(*views);
    }
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
    synthetic::validate(options);
  } catch (const std::exception& e) {
    std::cerr << "make_scene: " << e.what() << " (try --help)\n";
    return kExitUsage;
  }

  try {
    const auto start = std::chrono::steady_clock::now();
    const synthetic::GeneratedScene generated = synthetic::generate(options);
    symmetry_segmentation::saveScene(generated.scene, args.output);
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
