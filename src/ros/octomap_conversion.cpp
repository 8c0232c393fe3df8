#include "symmetry_segmentation/ros/octomap_conversion.h"

#include <sstream>
#include <string>

#include <octomap/OcTree.h>

#include "symmetry_segmentation/errors.h"
#include "symmetry_segmentation/scene_io.h"

namespace symmetry_segmentation {
namespace {

std::vector<int8_t> bytesOf(const std::stringstream& stream) {
  const std::string text = stream.str();
  return std::vector<int8_t>(text.begin(), text.end());
}

std::string describe(const OctomapMessage& message) {
  return std::string(message.binary ? "binary" : "full") + " octomap message (id '" + message.id + "', resolution " +
         std::to_string(message.resolution) + ", " + std::to_string(message.data.size()) + " bytes)";
}

}  // namespace

std::shared_ptr<octomap::OcTree> occupancyFromMessage(const OctomapMessage& message) {
  if (!(message.resolution > 0.0)) throw InputError(describe(message) + ": resolution must be positive");
  if (message.data.empty()) throw InputError(describe(message) + ": no data");
  // Binary data holds the tree structure and free/occupied bits only: the same for OcTree and
  // ColorOcTree, so both are read as an OcTree. Either encoding goes through the core's checked
  // reader: OctoMap's own readers follow garbage child bits past the data and past the tree's
  // 16 levels (found by fuzzing: a few bytes of binary data gave a tree 17+ levels deep).
  if (message.id != "OcTree" && message.id != "ColorOcTree") {
    throw InputError(describe(message) + ": unsupported tree type (expected OcTree or ColorOcTree)");
  }
  const OctreeEncoding encoding = message.binary                ? OctreeEncoding::Binary
                                  : message.id == "ColorOcTree" ? OctreeEncoding::FullColor
                                                                : OctreeEncoding::Full;
  const std::string data(message.data.begin(), message.data.end());
  return readOctreeData(describe(message), data, encoding, message.resolution);
}

OctomapMessage binaryMessageFromTree(const octomap::OcTree& tree) {
  OctomapMessage message;
  message.binary = true;
  message.id = tree.getTreeType();
  message.resolution = tree.getResolution();
  std::stringstream stream(std::ios::in | std::ios::out | std::ios::binary);
  tree.writeBinaryData(stream);
  message.data = bytesOf(stream);
  return message;
}

OctomapMessage fullMessageFromTree(const octomap::AbstractOcTree& tree) {
  OctomapMessage message;
  message.binary = false;
  message.id = tree.getTreeType();
  message.resolution = tree.getResolution();
  std::stringstream stream(std::ios::in | std::ios::out | std::ios::binary);
  tree.writeData(stream);
  message.data = bytesOf(stream);
  return message;
}

}  // namespace symmetry_segmentation
