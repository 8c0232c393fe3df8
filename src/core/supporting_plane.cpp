// The supporting surface: RANSAC on a coarse copy of the cloud (the table is large and flat,
// so 1-2 cm voxels lose nothing and keep RANSAC fast on dense clouds).
#include <pcl/ModelCoefficients.h>
#include <pcl/PointIndices.h>
#include <pcl/sample_consensus/method_types.h>
#include <pcl/sample_consensus/model_types.h>
#include <pcl/segmentation/sac_segmentation.h>

#include "symmetry_segmentation/preprocessing.h"

namespace symmetry_segmentation {

bool estimateSupportingPlane(const Cloud& cloud, const PreprocessParams& params, PlaneCoefficients& plane) {
  if (cloud.size() < 3) return false;
  pcl::SACSegmentation<PointT> ransac;
  ransac.setOptimizeCoefficients(true);
  ransac.setModelType(pcl::SACMODEL_PLANE);
  ransac.setMethodType(pcl::SAC_RANSAC);
  ransac.setDistanceThreshold(params.ransac_distance);
  ransac.setMaxIterations(params.ransac_iterations);
  ransac.setInputCloud(cloud.makeShared());
  pcl::PointIndices inliers;
  pcl::ModelCoefficients coefficients;
  ransac.segment(inliers, coefficients);
  // A "table" holding under a tenth of the scene is more likely an object face.
  if (coefficients.values.size() != 4 || inliers.indices.size() < std::max<std::size_t>(50, cloud.size() / 10)) {
    return false;
  }
  plane = PlaneCoefficients(coefficients.values[0], coefficients.values[1], coefficients.values[2],
                            coefficients.values[3]);
  const float norm = plane.head<3>().norm();
  if (!(norm > 1e-6f)) return false;
  plane /= norm;
  return true;
}

}  // namespace symmetry_segmentation
