#include "symmetry_segmentation/ros/moved_map_cache.h"

#include <utility>

namespace symmetry_segmentation {

MovedMapCache::MovedMapCache(Builder builder, double slack) : builder_(std::move(builder)), slack_(slack) {}

std::shared_ptr<octomap::OcTree> MovedMapCache::get(const std::shared_ptr<octomap::OcTree>& source,
                                                    const std::string& frame, const Eigen::Isometry3d& source_to_frame,
                                                    const Eigen::AlignedBox3d& box) {
  // One entry, built under the lock: concurrent calls for the same map wait for it once.
  std::lock_guard<std::mutex> lock(mutex_);
  if (entry_.tree && entry_.source == source && entry_.frame == frame &&
      entry_.source_to_frame.matrix() == source_to_frame.matrix() && entry_.region.contains(box)) {
    return entry_.tree;
  }
  entry_ = Entry();  // the old copy goes before the new one is built
  const Eigen::Vector3d slack = Eigen::Vector3d::Constant(slack_);
  const Eigen::AlignedBox3d region(box.min() - slack, box.max() + slack);
  auto tree = builder_(*source, source_to_frame, region);
  ++builds_;
  entry_ = Entry{source, frame, source_to_frame, region, tree};
  return tree;
}

void MovedMapCache::clear() {
  std::lock_guard<std::mutex> lock(mutex_);
  entry_ = Entry();
}

std::size_t MovedMapCache::builds() const {
  std::lock_guard<std::mutex> lock(mutex_);
  return builds_;
}

}  // namespace symmetry_segmentation
