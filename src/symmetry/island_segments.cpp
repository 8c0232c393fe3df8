// Stage 5a: islands that one plane explains (see the header for why).
#include "symmetry_segmentation/symmetry/island_segments.h"

#include <algorithm>

#include <pcl/search/kdtree.h>
#include <pcl/segmentation/extract_clusters.h>

#include "symmetry_segmentation/symmetry/sorted_indices.h"

namespace symmetry_segmentation {
namespace {

// A segment lends its plane to an island when at least this share of it lies on the island...
constexpr float kMinShareOnIsland = 0.5f;
// ...and it covers at least this share of the island: a piece of the object, not a detail of a
// large island of many objects (whose scoring under every plane would cost more than the cuts).
constexpr float kMinShareOfIsland = 0.3f;

}  // namespace

std::vector<std::vector<int>> spatialIslands(const Cloud::ConstPtr& cloud, float gap, int min_points) {
  std::vector<std::vector<int>> islands;
  if (!cloud || cloud->empty()) return islands;
  pcl::EuclideanClusterExtraction<PointT> extraction;
  extraction.setClusterTolerance(gap);
  extraction.setMinClusterSize(std::max(1, min_points));
  extraction.setMaxClusterSize(static_cast<int>(cloud->size()));
  extraction.setSearchMethod(std::make_shared<pcl::search::KdTree<PointT>>());
  extraction.setInputCloud(cloud);
  std::vector<pcl::PointIndices> clusters;
  extraction.extract(clusters);
  for (auto& cluster : clusters) {
    std::vector<int> island(cluster.indices.begin(), cluster.indices.end());
    std::sort(island.begin(), island.end());
    islands.push_back(std::move(island));
  }
  return islands;
}

std::vector<CandidateSegment> explainedIslands(const std::vector<std::vector<int>>& islands,
                                               const std::vector<CandidateSegment>& segments,
                                               const SegmentScorer& score, const SymmetryFilterParams& filter) {
  std::vector<CandidateSegment> result;
  for (const std::vector<int>& island : islands) {
    CandidateSegment best;
    bool found = false;
    for (const CandidateSegment& segment : segments) {
      if (segment.points.empty()) continue;
      const std::size_t common = intersectionSize(segment.points, island);
      if (common < kMinShareOnIsland * segment.points.size() || common < kMinShareOfIsland * island.size()) continue;
      CandidateSegment candidate;
      candidate.points = island;
      candidate.plane = segment.plane;
      candidate.scores = score(island, segment.plane);
      if (!found || candidate.scores.occlusion > best.scores.occlusion) {
        best = std::move(candidate);
        found = true;
      }
    }
    if (found && passesFilter(best, filter)) result.push_back(std::move(best));
  }
  return result;
}

}  // namespace symmetry_segmentation
