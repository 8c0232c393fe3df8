// The table's top as a quadratic height field over its plane (see the header for why).
#include "symmetry_segmentation/table_surface.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <utility>

#include <Eigen/Dense>

#include "symmetry_segmentation/quantile.h"

namespace symmetry_segmentation {
namespace {

constexpr std::size_t kMinCellPoints = 5;
constexpr std::size_t kMaxSampledPoints = 60000;
// A quadratic has six terms: a few cells per term before its bends mean anything.
constexpr std::size_t kMinCells = 24;
constexpr float kFacingCos = 0.8f;  // within ~37 deg of the table's normal
constexpr std::size_t kMinFacing = 100;
// A cell further off the surface than this many robust sigmas (and this many metres) is not the
// table's: a board or a book lying on it, an object's foot.
constexpr float kOutlierSigmas = 3.0f;
constexpr float kMinOutlierDistance = 0.002f;
constexpr int kRobustRounds = 5;
// Rounds of gathering the band around the last surface: a far table that bent out of the band
// around the plane comes back into it around the first surface.
constexpr int kGatherRounds = 2;
// Keeps the normal equations invertible where the cells lie along a line (a narrow table).
constexpr double kRidge = 1e-6;
// Cells spread less than this many cell widths across (a strip along one line) tilt a plane
// through them about that line at will: they tell no plane.
constexpr double kMinCrossSpreadCells = 2.0;

struct CellSample {
  float u = 0.0f, v = 0.0f;  ///< Mean place on the plane (m).
  float height = 0.0f;       ///< Median height over the plane (m).
};

/// The robust sigma of `values` about their median (1.4826 MAD).
float robustSigma(std::vector<float> values) {
  const float median = quantileOf(values, 0.5f);
  for (float& value : values) value = std::fabs(value - median);
  return 1.4826f * quantileOf(values, 0.5f);
}

}  // namespace

TableSurface::TableSurface(const PlaneCoefficients& plane, const Eigen::Vector3f& origin)
    : up_(plane.head<3>().normalized()),
      e1_(up_.unitOrthogonal()),
      e2_(up_.cross(e1_)),
      origin_(origin),
      offset_(plane[3] / plane.head<3>().norm()) {}

Eigen::Vector<float, 6> TableSurface::terms(const Eigen::Vector3f& p) const {
  const float x = e1_.dot(p - origin_) / scale_, y = e2_.dot(p - origin_) / scale_;
  Eigen::Vector<float, 6> t;
  t << 1.0f, x, y, x * x, x * y, y * y;
  return t;
}

float TableSurface::lift(const Eigen::Vector3f& p) const {
  return std::clamp(terms(p).dot(coefficients_), -max_lift_, max_lift_);
}

float TableSurface::height(const Eigen::Vector3f& p) const { return up_.dot(p) + offset_ - lift(p); }

std::optional<TableSurface> TableSurface::fit(const Cloud& cloud, const std::vector<int>& indices,
                                              const PlaneCoefficients& plane, float band, bool facing_up, float cell) {
  if (!(plane.head<3>().norm() > 0.0f) || !(band > 0.0f) || !(cell > 0.0f) || indices.empty()) return std::nullopt;
  TableSurface surface(plane, Eigen::Vector3f::Zero());
  std::optional<TableSurface> fitted;
  // Every stride-th point: a camera frame's 2 cm cell holds some 100 pixels, a score of them tell.
  const std::size_t stride = std::max<std::size_t>(1, indices.size() / kMaxSampledPoints);
  for (int round = 0; round < kGatherRounds; ++round) {
    // The band around the current surface, binned into cells by place on the plane.
    const auto gather = [&](bool facing_only) {
      std::vector<std::pair<std::int64_t, Eigen::Vector3f>> binned;  // (cell, (u, v, height over the plane))
      for (std::size_t k = 0; k < indices.size(); k += stride) {
        const PointT& point = cloud.points[indices[k]];
        const Eigen::Vector3f p = point.getVector3fMap();
        if (!(std::fabs(surface.height(p)) < band)) continue;
        if (facing_only && !(std::fabs(point.getNormalVector3fMap().dot(surface.up_)) >= kFacingCos)) continue;
        const float u = surface.e1_.dot(p), v = surface.e2_.dot(p);
        if (!(std::max(std::fabs(u), std::fabs(v)) / cell < 1e9f)) continue;
        const auto cu = static_cast<std::int64_t>(std::floor(u / cell));
        const auto cv = static_cast<std::int64_t>(std::floor(v / cell));
        binned.emplace_back(cu * (std::int64_t{1} << 32) + cv, Eigen::Vector3f(u, v, surface.up_.dot(p) + surface.offset_));
      }
      return binned;
    };
    auto binned = gather(facing_up);
    if (facing_up && binned.size() < kMinFacing) binned = gather(false);
    std::sort(binned.begin(), binned.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
    std::vector<CellSample> samples;
    std::vector<float> heights;
    for (std::size_t first = 0; first < binned.size();) {
      std::size_t last = first;
      Eigen::Vector2f place = Eigen::Vector2f::Zero();
      heights.clear();
      for (; last < binned.size() && binned[last].first == binned[first].first; ++last) {
        place += binned[last].second.head<2>();
        heights.push_back(binned[last].second.z());
      }
      if (heights.size() >= kMinCellPoints) {
        place /= static_cast<float>(heights.size());
        samples.push_back({place.x(), place.y(), quantileOf(heights, 0.5f)});
      }
      first = last;
    }
    if (samples.size() < kMinCells) break;
    if (round == 0) {  // the origin and scale: the cells' middle and spread
      Eigen::Vector2f middle = Eigen::Vector2f::Zero();
      for (const CellSample& s : samples) middle += Eigen::Vector2f(s.u, s.v);
      middle /= static_cast<float>(samples.size());
      float spread = 0.0f;
      for (const CellSample& s : samples) spread += (Eigen::Vector2f(s.u, s.v) - middle).squaredNorm();
      surface.origin_ = surface.e1_ * middle.x() + surface.e2_ * middle.y();
      surface.scale_ = std::max(std::sqrt(spread / static_cast<float>(samples.size())), cell);
    }
    const auto placeOf = [&](const CellSample& s) { return Eigen::Vector3f(surface.e1_ * s.u + surface.e2_ * s.v); };
    // Robust least squares: cells far off the last fit are left out of the next.
    std::vector<float> residuals(samples.size());
    const auto residualsOf = [&](const TableSurface& of) {
      for (std::size_t c = 0; c < samples.size(); ++c) residuals[c] = samples[c].height - of.lift(placeOf(samples[c]));
    };
    TableSurface candidate = surface;
    candidate.max_lift_ = band;
    residualsOf(candidate);
    // The cells within kOutlierSigmas robust sigmas of the residuals' median.
    const auto keptCells = [&]() {
      std::vector<float> sorted = residuals;
      const float median = quantileOf(sorted, 0.5f);
      const float limit = std::max(kOutlierSigmas * robustSigma(residuals), kMinOutlierDistance);
      std::vector<bool> kept(samples.size());
      for (std::size_t c = 0; c < samples.size(); ++c) kept[c] = std::fabs(residuals[c] - median) <= limit;
      return kept;
    };
    for (int pass = 0; pass < kRobustRounds; ++pass) {
      const std::vector<bool> kept = keptCells();
      Eigen::Matrix<double, 6, 6> normal = Eigen::Matrix<double, 6, 6>::Identity() * kRidge;
      Eigen::Vector<double, 6> rhs = Eigen::Vector<double, 6>::Zero();
      std::size_t used = 0;
      for (std::size_t c = 0; c < samples.size(); ++c) {
        if (!kept[c]) continue;
        const Eigen::Vector<double, 6> t = candidate.terms(placeOf(samples[c])).cast<double>();
        normal += t * t.transpose();
        rhs += t * static_cast<double>(samples[c].height);
        ++used;
      }
      if (used < kMinCells) break;
      candidate.coefficients_ = normal.ldlt().solve(rhs).cast<float>();
      candidate.cells_ = used;
      residualsOf(candidate);
    }
    if (candidate.cells_ < kMinCells) break;
    // Beyond the cells it was fitted to a quadratic runs off: lifts are held within the largest seen there.
    float max_lift = 0.0f;
    for (const CellSample& s : samples) {
      max_lift = std::max(max_lift, std::fabs(candidate.terms(placeOf(s)).dot(candidate.coefficients_)));
    }
    candidate.max_lift_ = std::min(max_lift, band);
    // The plane through the cells the fit kept: the table's own plane, whichever plane it began from.
    {
      const std::vector<bool> kept_cells = keptCells();
      Eigen::Vector3d mean = Eigen::Vector3d::Zero();
      std::vector<Eigen::Vector3d> kept;
      for (std::size_t c = 0; c < samples.size(); ++c) {
        if (!kept_cells[c]) continue;
        kept.push_back((placeOf(samples[c]) + surface.up_ * (samples[c].height - surface.offset_)).cast<double>());
        mean += kept.back();
      }
      if (kept.size() < kMinCells) break;
      mean /= static_cast<double>(kept.size());
      Eigen::Matrix3d scatter = Eigen::Matrix3d::Zero();
      for (const auto& q : kept) scatter += (q - mean) * (q - mean).transpose();
      Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> solver(scatter);
      const double cross_spread = std::sqrt(std::max(0.0, solver.eigenvalues()(1)) / static_cast<double>(kept.size()));
      if (cross_spread < kMinCrossSpreadCells * static_cast<double>(cell)) break;
      Eigen::Vector3d normal = solver.eigenvectors().col(0);
      if (normal.dot(surface.up_.cast<double>()) < 0.0) normal = -normal;
      candidate.plane_ << normal.cast<float>(), static_cast<float>(-normal.dot(mean));
    }
    surface = candidate;
    fitted = candidate;
  }
  return fitted;
}

}  // namespace symmetry_segmentation
