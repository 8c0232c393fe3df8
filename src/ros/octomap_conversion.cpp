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

std::shared_ptr<octomap::OcTree> resampleOccupancy(const octomap::OcTree& source, const Eigen::Isometry3d& source_to_target,
                                                   const Eigen::AlignedBox3d& region, std::size_t max_voxels) {
  const double resolution = source.getResolution();
  auto target = std::make_shared<octomap::OcTree>(resolution);
  target->setOccupancyThres(source.getOccupancyThres());
  target->setProbHit(source.getProbHit());
  target->setProbMiss(source.getProbMiss());
  target->setClampingThresMin(source.getClampingThresMin());
  target->setClampingThresMax(source.getClampingThresMax());
  if (region.isEmpty() || !region.min().allFinite() || !region.max().allFinite()) {
    throw InputError("cannot move an OctoMap into another frame over an empty or non-finite region");
  }
  octomap::OcTreeKey low, high;
  if (!target->coordToKeyChecked(octomap::point3d(region.min().x(), region.min().y(), region.min().z()), low) ||
      !target->coordToKeyChecked(octomap::point3d(region.max().x(), region.max().y(), region.max().z()), high)) {
    throw InputError("region for the OctoMap lies outside the volume an OctoMap can represent");
  }
  const std::size_t voxels = (static_cast<std::size_t>(high[0]) - low[0] + 1) *
                             (static_cast<std::size_t>(high[1]) - low[1] + 1) * (static_cast<std::size_t>(high[2]) - low[2] + 1);
  if (voxels > max_voxels) {
    throw InputError("moving the OctoMap into the processing frame needs " + std::to_string(voxels) +
                     " voxels around the cloud, more than " + std::to_string(max_voxels));
  }
  const Eigen::Isometry3d target_to_source = source_to_target.inverse();
  octomap::OcTreeKey key;
  for (unsigned x = low[0]; x <= high[0]; ++x) {
    for (unsigned y = low[1]; y <= high[1]; ++y) {
      for (unsigned z = low[2]; z <= high[2]; ++z) {
        key[0] = static_cast<octomap::key_type>(x);
        key[1] = static_cast<octomap::key_type>(y);
        key[2] = static_cast<octomap::key_type>(z);
        const octomap::point3d centre = target->keyToCoord(key);
        const Eigen::Vector3d in_source = target_to_source * Eigen::Vector3d(centre.x(), centre.y(), centre.z());
        const octomap::OcTreeNode* node = source.search(in_source.x(), in_source.y(), in_source.z());
        if (node) target->setNodeValue(key, node->getLogOdds(), true);
      }
    }
  }
  target->updateInnerOccupancy();
  target->prune();
  return target;
}

}  // namespace symmetry_segmentation
