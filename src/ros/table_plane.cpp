#include "symmetry_segmentation/ros/table_plane.h"

#include <cmath>
#include <sstream>

#include "symmetry_segmentation/errors.h"
#include "symmetry_segmentation/point_validity.h"

namespace symmetry_segmentation {

Eigen::Vector4d planeFromCoefficients(const std::vector<double>& values) {
  if (values.size() != 4) {
    throw InputError("a plane needs 4 coefficients [a, b, c, d] (a x + b y + c z + d = 0), got " +
                     std::to_string(values.size()));
  }
  const Eigen::Vector4d plane(values[0], values[1], values[2], values[3]);
  if (!plane.allFinite()) {
    std::ostringstream text;
    text << "plane coefficients [" << plane.transpose() << "] are not all finite";
    throw InputError(text.str());
  }
  // Scaled before the norm, as the core reads table_plane.txt: huge or tiny values stay finite.
  const double scale = plane.head<3>().cwiseAbs().maxCoeff();
  if (!(scale > 0.0)) throw InputError("plane normal (a, b, c) is zero");
  Eigen::Vector4d unit = plane / scale;
  unit /= unit.head<3>().norm();
  if (!unit.allFinite() || std::fabs(unit[3]) > kMaxUsableCoordinate) {
    throw InputError("plane offset d / |(a, b, c)| is not finite or farther than 100 km");
  }
  return unit;
}

Eigen::Vector4d transformPlane(const Eigen::Vector4d& plane, const Eigen::Isometry3d& source_to_target) {
  // pi_target^T p_target = pi_source^T p_source for every point: pi_target = T^-T pi_source.
  return source_to_target.matrix().inverse().transpose() * plane;
}

PlaneCoefficients toPlaneCoefficients(const Eigen::Vector4d& plane) {
  return (plane / plane.head<3>().norm()).cast<float>();
}

}  // namespace symmetry_segmentation
