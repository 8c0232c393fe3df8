#pragma once
// OctoMap trees <-> octomap_msgs/Octomap messages (binary or full), as octomap_server sends them.

#include <cstddef>
#include <memory>

#include <Eigen/Geometry>

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

/// `source` (in its own frame) expressed in another frame over `region` (target frame): every
/// voxel of a tree with the source's resolution whose centre lies in `region` takes the
/// source's occupancy (log-odds) at that centre mapped back by `source_to_target`.inverse();
/// voxels the source never observed stay unknown. Exact for grid-aligned motions (translations
/// by whole voxels, quarter turns). Throws InputError when `region` is empty, not finite, or holds
/// more than `max_voxels` voxels.
std::shared_ptr<octomap::OcTree> resampleOccupancy(const octomap::OcTree& source, const Eigen::Isometry3d& source_to_target,
                                                   const Eigen::AlignedBox3d& region,
                                                   std::size_t max_voxels = 32u << 20);

/// Binary (free/occupied only) message of `tree`; the header is left for the caller.
OctomapMessage binaryMessageFromTree(const octomap::OcTree& tree);

/// Full message (node data of any tree type, id = the tree's type); header left for the caller.
OctomapMessage fullMessageFromTree(const octomap::AbstractOcTree& tree);

}  // namespace symmetry_segmentation
