// Occupancy from one organized frame's depth (see the header for why).
#include "symmetry_segmentation/depth_image_occupancy.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include <Eigen/Eigenvalues>

namespace symmetry_segmentation {
namespace {

constexpr std::size_t kMinValidPixels = 100;
constexpr std::size_t kTargetSamples = 4000;  // the fit is exact up to noise: a few thousand pixels do
constexpr double kMaxReprojectionError = 1.0;  // pixels: beyond it the frame is no pinhole image
// Relative to the largest: real frames give 1e-4 .. 1e-3, a bare plane 1e-17.
constexpr double kMinSecondEigenvalue = 1e-6;

struct PixelSample {
  Eigen::Vector3d point;
  Eigen::Vector2d pixel;
};

// Hartley's normalisation: centred, mean distance sqrt(dim), so the DLT's system is well conditioned.
template <int Dim>
Eigen::Matrix<double, Dim + 1, Dim + 1> normalisingTransform(const std::vector<Eigen::Matrix<double, Dim, 1>>& points) {
  Eigen::Matrix<double, Dim, 1> mean = Eigen::Matrix<double, Dim, 1>::Zero();
  for (const auto& p : points) mean += p;
  mean /= static_cast<double>(points.size());
  double spread = 0.0;
  for (const auto& p : points) spread += (p - mean).norm();
  spread /= static_cast<double>(points.size());
  const double scale = spread > 0.0 ? std::sqrt(static_cast<double>(Dim)) / spread : 1.0;
  Eigen::Matrix<double, Dim + 1, Dim + 1> t = Eigen::Matrix<double, Dim + 1, Dim + 1>::Identity();
  t.template topLeftCorner<Dim, Dim>() *= scale;
  t.template topRightCorner<Dim, 1>() = -scale * mean;
  return t;
}

// The 3x4 projection taking each sample's point to its pixel (direct linear transform).
bool fitProjection(const std::vector<PixelSample>& samples, Eigen::Matrix<double, 3, 4>& projection) {
  std::vector<Eigen::Vector3d> points;
  std::vector<Eigen::Vector2d> pixels;
  for (const PixelSample& s : samples) {
    points.push_back(s.point);
    pixels.push_back(s.pixel);
  }
  const Eigen::Matrix4d t3 = normalisingTransform<3>(points);
  const Eigen::Matrix3d t2 = normalisingTransform<2>(pixels);
  Eigen::Matrix<double, 12, 12> normal_matrix = Eigen::Matrix<double, 12, 12>::Zero();
  for (std::size_t i = 0; i < samples.size(); ++i) {
    const Eigen::Vector4d x = t3 * points[i].homogeneous();
    const Eigen::Vector3d uv = t2 * pixels[i].homogeneous();
    Eigen::Matrix<double, 2, 12> rows = Eigen::Matrix<double, 2, 12>::Zero();
    rows.block<1, 4>(0, 0) = x.transpose();
    rows.block<1, 4>(0, 8) = -uv.x() * x.transpose();
    rows.block<1, 4>(1, 4) = x.transpose();
    rows.block<1, 4>(1, 8) = -uv.y() * x.transpose();
    normal_matrix.noalias() += rows.transpose() * rows;
  }
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix<double, 12, 12>> solver(normal_matrix);
  if (solver.info() != Eigen::Success) return false;
  // One camera fits: a second near-null direction means many do (every point on one plane).
  const auto& eigenvalues = solver.eigenvalues();
  if (!(eigenvalues(1) > kMinSecondEigenvalue * eigenvalues(11))) return false;
  const Eigen::Matrix<double, 12, 1> p = solver.eigenvectors().col(0);  // smallest eigenvalue
  Eigen::Matrix<double, 3, 4> normalised;
  normalised << p.segment<4>(0).transpose(), p.segment<4>(4).transpose(), p.segment<4>(8).transpose();
  projection = t2.inverse() * normalised * t3;
  return projection.allFinite();
}

}  // namespace

std::shared_ptr<const DepthImageOccupancy> DepthImageOccupancy::fromOrganizedCloud(const Cloud& frame,
                                                                                   float surface_thickness) {
  if (!frame.isOrganized() || frame.width < 2 || frame.height < 2) return nullptr;
  const int width = static_cast<int>(frame.width);
  const int height = static_cast<int>(frame.height);
  std::size_t valid = 0;
  for (const PointT& p : frame.points) valid += std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z);
  if (valid < kMinValidPixels) return nullptr;

  // An even spread of valid pixels over the image (every stride-th one in scan order).
  const std::size_t stride = std::max<std::size_t>(1, valid / kTargetSamples);
  std::vector<PixelSample> samples;
  std::size_t seen = 0;
  for (int row = 0; row < height; ++row) {
    for (int col = 0; col < width; ++col) {
      const PointT& p = frame.at(col, row);
      if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z)) continue;
      if (seen++ % stride == 0) samples.push_back({p.getVector3fMap().cast<double>(), Eigen::Vector2d(col, row)});
    }
  }
  std::shared_ptr<DepthImageOccupancy> result(new DepthImageOccupancy());
  if (!fitProjection(samples, result->projection_)) return nullptr;

  // The points lie in front of the camera: fix the projection's overall sign so depth is positive.
  double in_front = 0.0;
  for (const PixelSample& s : samples) in_front += result->projection_.row(2).dot(s.point.homogeneous()) > 0.0 ? 1 : -1;
  if (in_front < 0.0) result->projection_ = -result->projection_;

  double squared_error = 0.0;
  for (const PixelSample& s : samples) {
    const Eigen::Vector3d uvw = result->projection_ * s.point.homogeneous();
    if (!(uvw.z() > 0.0)) return nullptr;  // a point behind the camera: not one view
    squared_error += (uvw.head<2>() / uvw.z() - s.pixel).squaredNorm();
  }
  result->reprojection_error_ = static_cast<float>(std::sqrt(squared_error / samples.size()));
  if (!(result->reprojection_error_ <= kMaxReprojectionError)) return nullptr;

  // The optical centre is the projection's null space: P [C; 1] = 0.
  const Eigen::Matrix3d m = result->projection_.leftCols<3>();
  if (std::fabs(m.determinant()) < 1e-12) return nullptr;
  result->center_ = (-m.inverse() * result->projection_.col(3)).cast<float>();
  if (!result->center_.allFinite()) return nullptr;

  result->width_ = width;
  result->height_ = height;
  result->thickness_ = surface_thickness;
  result->range_.assign(frame.size(), std::numeric_limits<float>::quiet_NaN());
  for (std::size_t i = 0; i < frame.size(); ++i) {
    const Eigen::Vector3f p = frame.points[i].getVector3fMap();
    if (p.allFinite()) result->range_[i] = (p - result->center_).norm();
  }
  return result;
}

bool DepthImageOccupancy::pixelOf(const Eigen::Vector3f& point, int& pixel) const {
  const Eigen::Vector3d uvw = projection_ * point.cast<double>().homogeneous();
  if (!(uvw.z() > 0.0)) return false;
  const double u = std::round(uvw.x() / uvw.z());
  const double v = std::round(uvw.y() / uvw.z());
  if (!(u >= 0.0 && v >= 0.0 && u < width_ && v < height_)) return false;
  pixel = static_cast<int>(v) * width_ + static_cast<int>(u);
  return true;
}

Occupancy DepthImageOccupancy::classify(const Eigen::Vector3f& point) const {
  int pixel = 0;
  if (!point.allFinite() || !pixelOf(point, pixel)) return Occupancy::Unknown;
  const float measured = range_[pixel];
  if (!std::isfinite(measured)) return Occupancy::Unknown;  // no return there: nothing was seen
  const float range = (point - center_).norm();
  if (range < measured - thickness_) return Occupancy::Free;
  if (range <= measured + thickness_) return Occupancy::Occupied;
  return Occupancy::Unknown;  // behind the surface the pixel saw
}

std::optional<Eigen::Vector3f> cameraCenterOfFrame(const Cloud& frame) {
  const auto occupancy = DepthImageOccupancy::fromOrganizedCloud(frame, 0.0f);
  if (!occupancy) return std::nullopt;
  return occupancy->cameraCenter();
}

}  // namespace symmetry_segmentation
