// Fuzz target: OctoMap .bt / .ot files through loadOctomapFile. The extension follows the magic
// line, so one target covers both encodings.
#include <cmath>
#include <cstring>

#include <octomap/OcTree.h>

#include "fuzz_support.h"
#include "symmetry_segmentation/errors.h"
#include "symmetry_segmentation/scene_io.h"

namespace ss = symmetry_segmentation;

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  static fuzz_support::ScratchFile bt("map.bt"), ot("map.ot");
  static const char kBinaryMagic[] = "# Octomap OcTree binary";
  const bool binary = size >= sizeof(kBinaryMagic) - 1 && std::memcmp(data, kBinaryMagic, sizeof(kBinaryMagic) - 1) == 0;
  const std::string& path = (binary ? bt : ot).write(data, size);
  std::shared_ptr<octomap::OcTree> tree;
  try {
    tree = ss::loadOctomapFile(path);
  } catch (const ss::InputError&) {
    return 0;
  }
  FUZZ_CHECK(tree);
  FUZZ_CHECK(tree->getResolution() >= 1e-4 && tree->getResolution() <= 10.0);
  FUZZ_CHECK(tree->getTreeDepth() == 16);
  // Every node the tree holds can be visited and queried where it sits.
  std::size_t leaves = 0;
  for (auto it = tree->begin_leafs(), end = tree->end_leafs(); it != end; ++it) {
    FUZZ_CHECK(it.getDepth() <= 16);
    FUZZ_CHECK(tree->search(it.getKey(), it.getDepth()) != nullptr);
    ++leaves;
  }
  FUZZ_CHECK(leaves == tree->getNumLeafNodes());
  return 0;
}
