#pragma once
// OctoMap trees <-> octomap_msgs/Octomap messages (binary or full), as octomap_server sends them.

#include <memory>

#include "symmetry_segmentation/ros/octomap_message.h"

namespace octomap {
class AbstractOcTree;
class OcTree;
}  // namespace octomap

namespace symmetry_segmentation {

/// The occupancy a message holds, as an OcTree. Binary messages are read as occupancy trees;
/// full ones are created by tree id and must be an OcTree or a ColorOcTree (whose occupancy is
/// kept, colours dropped). Throws InputError for any other tree type or unreadable data.
std::shared_ptr<octomap::OcTree> occupancyFromMessage(const OctomapMessage& message);

/// Binary (free/occupied only) message of `tree`; the header is left for the caller.
OctomapMessage binaryMessageFromTree(const octomap::OcTree& tree);

/// Full message (node data of any tree type, id = the tree's type); header left for the caller.
OctomapMessage fullMessageFromTree(const octomap::AbstractOcTree& tree);

}  // namespace symmetry_segmentation
