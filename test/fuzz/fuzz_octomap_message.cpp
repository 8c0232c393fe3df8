// Fuzz target: octomap_msgs/Octomap message data through occupancyFromMessage.
// Input layout: 1 byte flags (bit 0: binary), 1 byte tree id (index into kIds), 8 bytes
// resolution (little-endian double), then the message's data bytes.
#include <octomap/OcTree.h>

#include "fuzz_support.h"
#include "symmetry_segmentation/errors.h"
#include "symmetry_segmentation/ros/octomap_conversion.h"

namespace ss = symmetry_segmentation;

namespace {
const char* const kIds[] = {"OcTree", "ColorOcTree", "OcTreeStamped", "CountingOcTree", "", "NoSuchTree"};
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  fuzz_support::ByteReader in(data, size);
  ss::OctomapMessage message;
  message.binary = (in.u8() & 1) != 0;
  message.id = kIds[in.u8() % (sizeof(kIds) / sizeof(kIds[0]))];
  message.resolution = in.f64();
  const std::string bytes = in.rest();
  message.data.assign(bytes.begin(), bytes.end());
  std::shared_ptr<octomap::OcTree> tree;
  try {
    tree = ss::occupancyFromMessage(message);
  } catch (const ss::InputError&) {
    return 0;
  }
  FUZZ_CHECK(tree);
  FUZZ_CHECK(tree->getResolution() == message.resolution);
  std::size_t leaves = 0;
  for (auto it = tree->begin_leafs(), end = tree->end_leafs(); it != end; ++it) {
    FUZZ_CHECK(it.getDepth() <= 16);
    ++leaves;
  }
  FUZZ_CHECK(leaves == tree->getNumLeafNodes());
  return 0;
}
