#include "symmetry_segmentation/plane_fit.h"

#include <pcl/ModelCoefficients.h>
#include <pcl/sample_consensus/method_types.h>
#include <pcl/sample_consensus/model_types.h>
#include <pcl/segmentation/sac_segmentation.h>

namespace symmetry_segmentation {

std::optional<PlaneCoefficients> fitLargestPlane(const Cloud::ConstPtr& cloud, double distance, int iterations,
                                                 pcl::PointIndices& inliers) {
  inliers.indices.clear();
  if (!cloud || cloud->size() < 3) return std::nullopt;
  pcl::SACSegmentation<PointT> ransac;
  ransac.setOptimizeCoefficients(true);
  ransac.setModelType(pcl::SACMODEL_PLANE);
  ransac.setMethodType(pcl::SAC_RANSAC);
  ransac.setDistanceThreshold(distance);
  ransac.setMaxIterations(iterations);
  ransac.setInputCloud(cloud);
  pcl::ModelCoefficients coefficients;
  ransac.segment(inliers, coefficients);
  if (coefficients.values.size() != 4 || inliers.indices.size() < 3) return std::nullopt;
  const PlaneCoefficients plane(coefficients.values[0], coefficients.values[1], coefficients.values[2],
                                coefficients.values[3]);
  const float norm = plane.head<3>().norm();
  if (!(norm > 1e-6f)) return std::nullopt;
  return PlaneCoefficients(plane / norm);
}

}  // namespace symmetry_segmentation
