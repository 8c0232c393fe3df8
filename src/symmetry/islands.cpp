// Stage 6, islands: Euclidean clusters of the working cloud (see the header for why).
#include "symmetry_segmentation/symmetry/islands.h"

#include <algorithm>

#include <pcl/search/kdtree.h>
#include <pcl/segmentation/extract_clusters.h>

#include "symmetry_segmentation/symmetry/pipeline_state.h"

namespace symmetry_segmentation {

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

void IslandStage::run(PipelineState& state) const {
  state.islands = spatialIslands(state.cloud, params_.gap, filter_.min_segment_points);
  state.count("islands", state.islands.size());
}

}  // namespace symmetry_segmentation
