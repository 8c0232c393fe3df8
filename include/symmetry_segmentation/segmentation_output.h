#pragma once
// Turning a segmentation into things a person can look at: a cloud coloured by segment
// (written as PLY) and a PNG picture rendered from the sensor's side.

#include <string>
#include <vector>

#include <pcl/point_cloud.h>
#include <pcl/point_types.h>

#include "symmetry_segmentation/scene.h"
#include "symmetry_segmentation/segmentation_result.h"

namespace symmetry_segmentation {

/// A distinct, reproducible colour for segment `index`.
Eigen::Vector3i segmentColor(std::size_t index);

/// Every input point, coloured by the first segment holding it; others keep a dimmed grey.
pcl::PointCloud<pcl::PointXYZRGB> colorBySegment(const Cloud& cloud, const std::vector<Segment>& segments);

/// The colour of what completion added to segment `index`: its colour halfway to white.
Eigen::Vector3i addedPointColor(std::size_t index);

/// Every segment's completion's added points (its unseen side), in addedPointColor.
pcl::PointCloud<pcl::PointXYZRGB> addedPoints(const std::vector<Segment>& segments);

/// Each segment's points in its colour and its completion's added points in addedPointColor;
/// nothing else.
pcl::PointCloud<pcl::PointXYZRGB> completedObjects(const Cloud& cloud, const std::vector<Segment>& segments);

void writeColoredPly(const pcl::PointCloud<pcl::PointXYZRGB>& cloud, const std::string& path);

struct View {
  Eigen::Vector3f eye;
  Eigen::Vector3f target;
  Eigen::Vector3f up;
};

/// A view from the scene's sensor (or from above the table) toward the segmented points.
View defaultView(const Scene& scene, const std::vector<Segment>& segments);

/// Z-buffered point splatting of `cloud` seen from `view`, written as an RGB PNG. The picture
/// is framed on the points `focus` indexes (every point when empty).
void renderPng(const pcl::PointCloud<pcl::PointXYZRGB>& cloud, const View& view, const std::string& path,
               const std::vector<int>& focus = {}, int width = 960, int height = 720);

/// The input points held by any segment, for framing pictures on the objects.
std::vector<int> segmentedPoints(const std::vector<Segment>& segments);

}  // namespace symmetry_segmentation
