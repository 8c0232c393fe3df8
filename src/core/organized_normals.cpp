// Normals from an organized frame's pixel grid (see the header for why).
#include "symmetry_segmentation/organized_normals.h"

#include <cmath>
#include <limits>
#include <memory>

#include <Eigen/Geometry>
#include <pcl/features/integral_image_normal.h>

namespace symmetry_segmentation {

Cloud::Ptr pointsWithOrganizedNormals(const Cloud& frame, const std::vector<int>& indices,
                                      const Eigen::Vector3f& viewpoint, float smoothing_pixels) {
  if (!frame.isOrganized() || frame.width < 3 || frame.height < 3) return nullptr;
  // The estimator takes z for the depth (depth jumps, the window's growth): the frame may have
  // been moved out of the camera's (a robot's base frame), so it sees the points from the
  // viewpoint, turned to look along their mean direction. Normals are turned back after.
  Eigen::Vector3f mean_direction = Eigen::Vector3f::Zero();
  for (std::size_t i = 0; i < frame.size(); i += 7) {
    const Eigen::Vector3f offset = frame.points[i].getVector3fMap() - viewpoint;
    if (offset.allFinite() && offset.norm() > 1e-6f) mean_direction += offset.normalized();
  }
  if (mean_direction.norm() < 1e-6f) mean_direction = Eigen::Vector3f::UnitZ();
  const Eigen::Matrix3f to_view =
      Eigen::Quaternionf::FromTwoVectors(mean_direction.normalized(), Eigen::Vector3f::UnitZ()).toRotationMatrix();
  auto positions = std::make_shared<pcl::PointCloud<pcl::PointXYZ>>(frame.width, frame.height);
  for (std::size_t i = 0; i < frame.size(); ++i) {
    positions->points[i].getVector3fMap() = to_view * (frame.points[i].getVector3fMap() - viewpoint);
  }
  positions->is_dense = false;

  pcl::IntegralImageNormalEstimation<pcl::PointXYZ, pcl::Normal> estimator;
  estimator.setNormalEstimationMethod(estimator.AVERAGE_3D_GRADIENT);
  // Neighbours across a depth jump of more than 2 % of the depth are another surface.
  estimator.setMaxDepthChangeFactor(0.02f);
  estimator.setNormalSmoothingSize(smoothing_pixels);
  estimator.setDepthDependentSmoothing(true);
  estimator.setViewPoint(0.0f, 0.0f, 0.0f);
  estimator.setInputCloud(positions);
  estimator.setIndices(std::make_shared<std::vector<int>>(indices));
  pcl::PointCloud<pcl::Normal> normals;
  estimator.compute(normals);
  // One per index, in their order; but with as many indices as pixels PCL computes the whole
  // image and returns it in pixel order, whatever the indices' order.
  const bool pixel_order = indices.size() == frame.size();

  auto points = std::make_shared<Cloud>();
  points->resize(indices.size());
  constexpr float kNaN = std::numeric_limits<float>::quiet_NaN();
  for (std::size_t k = 0; k < indices.size(); ++k) {
    PointT& p = points->points[k];
    p = frame.points[indices[k]];
    const std::size_t at = pixel_order ? static_cast<std::size_t>(indices[k]) : k;
    const pcl::Normal* n = at < normals.size() ? &normals.points[at] : nullptr;
    const bool valid = n && std::isfinite(n->normal_x) && std::isfinite(n->normal_y) && std::isfinite(n->normal_z);
    const Eigen::Vector3f normal =
        valid ? Eigen::Vector3f(to_view.transpose() * Eigen::Vector3f(n->normal_x, n->normal_y, n->normal_z))
              : Eigen::Vector3f::Constant(kNaN);
    p.normal_x = normal.x();
    p.normal_y = normal.y();
    p.normal_z = normal.z();
    p.curvature = valid ? n->curvature : kNaN;
  }
  return points;
}

}  // namespace symmetry_segmentation
