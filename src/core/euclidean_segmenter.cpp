#include <algorithm>

#include <pcl/search/kdtree.h>
#include <pcl/segmentation/extract_clusters.h>

#include "symmetry_segmentation/baseline_segmenters.h"
#include "symmetry_segmentation/object_bottoms.h"
#include "symmetry_segmentation/segment_order.h"
#include "symmetry_segmentation/object_box.h"
#include "symmetry_segmentation/stopwatch.h"

namespace symmetry_segmentation {

SegmentationResult EuclideanSegmenter::segment(const Scene& scene) const {
  Stopwatch total, stage;
  SegmentationResult result;
  result.input_points = scene.size();
  const PreprocessedScene prepared = preprocess(scene, preprocessing_);
  result.support = supportSurface(prepared);
  result.timing_ms.emplace_back("preprocess", stage.lap());

  pcl::EuclideanClusterExtraction<PointT> extraction;
  extraction.setClusterTolerance(params_.cluster_tolerance);
  extraction.setMinClusterSize(std::max(1, params_.min_cluster_size));
  extraction.setMaxClusterSize(params_.max_cluster_size);
  extraction.setSearchMethod(std::make_shared<pcl::search::KdTree<PointT>>());
  extraction.setInputCloud(prepared.cloud);
  std::vector<pcl::PointIndices> clusters;
  extraction.extract(clusters);
  for (const auto& cluster : clusters) {
    Segment segment;
    segment.indices = expandToInput(prepared, cluster.indices);
    result.segments.push_back(std::move(segment));
  }
  if (params_.restore_object_bottoms) {
    restoreObjectBottoms(scene, prepared, preprocessing_.voxel_size, result.segments, bottoms_);
  }
  sortSegmentsBySize(result.segments);
  addObjectBoxes(scene, result);
  result.timing_ms.emplace_back("clustering", stage.lap());
  result.timing_ms.emplace_back("total", total.elapsedMs());
  return result;
}

}  // namespace symmetry_segmentation
