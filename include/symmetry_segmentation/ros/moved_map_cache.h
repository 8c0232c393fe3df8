#pragma once
// The OctoMap of another frame, moved into the processing frame over a region, kept for the
// next cloud: moving a map takes a noticeable fraction of a segmentation, and consecutive clouds
// of one scene ask for the same map, frame, transform and (nearly) the same region.
// ROS-free (std, Eigen, OctoMap): unit-tested without a master.

#include <cstddef>
#include <functional>
#include <memory>
#include <mutex>
#include <string>

#include <Eigen/Geometry>

namespace octomap {
class OcTree;
}

namespace symmetry_segmentation {

class MovedMapCache {
 public:
  /// Builds `source` moved by `source_to_frame` over `region` (in the target frame).
  using Builder = std::function<std::shared_ptr<octomap::OcTree>(
      const octomap::OcTree& source, const Eigen::Isometry3d& source_to_frame, const Eigen::AlignedBox3d& region)>;

  /// `slack` (m) is added around every region built, so the next cloud of a slightly different
  /// extent still fits.
  MovedMapCache(Builder builder, double slack);

  /// `source` moved into `frame` over a region containing `box`: the cached copy when the source
  /// (the same tree object), frame and transform are the same and its region contains `box`;
  /// otherwise built anew (the previous copy is released first) and cached. Concurrent callers
  /// for the same map wait for one build. Exceptions of the builder pass through (nothing is
  /// cached then).
  std::shared_ptr<octomap::OcTree> get(const std::shared_ptr<octomap::OcTree>& source, const std::string& frame,
                                       const Eigen::Isometry3d& source_to_frame, const Eigen::AlignedBox3d& box);

  /// Forgets the cached copy (e.g. when ROS time jumped back: the transform may be stale).
  void clear();

  /// Times the builder ran.
  std::size_t builds() const;

 private:
  struct Entry {
    std::shared_ptr<octomap::OcTree> source;
    std::string frame;
    Eigen::Isometry3d source_to_frame = Eigen::Isometry3d::Identity();
    Eigen::AlignedBox3d region;
    std::shared_ptr<octomap::OcTree> tree;
  };

  Builder builder_;
  double slack_;
  mutable std::mutex mutex_;
  Entry entry_;
  std::size_t builds_ = 0;
};

}  // namespace symmetry_segmentation
