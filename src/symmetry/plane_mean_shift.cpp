// Mean shift over symmetry planes. Planes are compared by normal angle and offset difference
// after aligning their orientation, so a plane and its sign-flipped copy are one sample, and
// planes through the origin are no special case.
#include <algorithm>
#include <cmath>
#include <tuple>

#include "symmetry_segmentation/symmetry/symmetry_hypotheses.h"
#include "symmetry_segmentation/symmetry/symmetry_plane.h"

namespace symmetry_segmentation {
namespace {

constexpr float kDegPerRad = 180.0f / static_cast<float>(M_PI);
// Fixed (numerical, not tunables of the method; the bandwidths are parameters):
constexpr int kMaxStarts = 400;      // More samples than this: start from an even subset (cost bound).
constexpr int kMaxIterations = 100;  // A mode has converged long before.
constexpr float kCutoff = 9.0f;      // Kernel support: 3 bandwidths (squared normalised distance).

bool planeLess(const SymmetryPlane& a, const SymmetryPlane& b) {
  return std::make_tuple(a.normal.x(), a.normal.y(), a.normal.z(), a.distance) <
         std::make_tuple(b.normal.x(), b.normal.y(), b.normal.z(), b.distance);
}

struct Kernel {
  float angle_bandwidth_deg;
  float distance_bandwidth;
  float min_cos;  // Normals farther apart than the cutoff are skipped before any acos.

  Kernel(float angle_deg, float distance)
      : angle_bandwidth_deg(angle_deg),
        distance_bandwidth(distance),
        min_cos(std::cos(std::min(90.0f, std::sqrt(kCutoff) * angle_deg) / kDegPerRad)) {}

  /// Squared distance in bandwidths, or a value above kCutoff when out of reach.
  float normalisedDistance(const SymmetryPlane& a, const SymmetryPlane& b) const {
    const float dot = a.normal.dot(b.normal);
    const float c = std::fabs(dot);
    if (c < min_cos) return kCutoff + 1.0f;
    const float offset = (dot >= 0.0f ? a.distance - b.distance : a.distance + b.distance) / distance_bandwidth;
    const float angle = std::acos(std::min(1.0f, c)) * kDegPerRad / angle_bandwidth_deg;
    return angle * angle + offset * offset;
  }
};

/// Follows the weighted mean from `start` until it stops moving.
SymmetryPlane climb(const std::vector<PlaneSample>& samples, const Kernel& kernel, SymmetryPlane mode) {
  for (int iteration = 0; iteration < kMaxIterations; ++iteration) {
    Eigen::Vector3f normal_sum = Eigen::Vector3f::Zero();
    float distance_sum = 0.0f, weight_sum = 0.0f;
    for (const PlaneSample& s : samples) {
      const float u = kernel.normalisedDistance(mode, s.plane);
      if (u > kCutoff) continue;
      const float w = s.weight * std::exp(-0.5f * u);
      const float sign = mode.normal.dot(s.plane.normal) >= 0.0f ? 1.0f : -1.0f;
      normal_sum += (w * sign) * s.plane.normal;
      distance_sum += w * sign * s.plane.distance;
      weight_sum += w;
    }
    if (weight_sum <= 0.0f || normal_sum.norm() < 1e-9f) break;
    SymmetryPlane next;
    next.normal = normal_sum.normalized();
    next.distance = distance_sum / weight_sum;
    const bool converged = planeAngleDeg(next, mode) < 1e-3f * kernel.angle_bandwidth_deg &&
                           planeDistanceDifference(next, mode) < 1e-3f * kernel.distance_bandwidth;
    mode = next;
    if (converged) break;
  }
  return canonicalPlane(mode);
}

}  // namespace

std::vector<SymmetryHypothesis> meanShiftPlanes(const std::vector<PlaneSample>& input, float angle_bandwidth_deg,
                                                float distance_bandwidth) {
  // A canonical order makes the result independent of the order the samples came in.
  std::vector<PlaneSample> samples = input;
  for (auto& s : samples) s.plane = canonicalPlane(s.plane);
  std::sort(samples.begin(), samples.end(), [](const PlaneSample& a, const PlaneSample& b) {
    if (planeLess(a.plane, b.plane)) return true;
    if (planeLess(b.plane, a.plane)) return false;
    return a.weight < b.weight;
  });
  const Kernel kernel(angle_bandwidth_deg, distance_bandwidth);

  struct Mode {
    SymmetryPlane plane;
    float support = 0.0f;
  };
  std::vector<Mode> modes;
  std::vector<int> mode_of(samples.size(), -1);
  const std::size_t stride = (samples.size() + kMaxStarts - 1) / kMaxStarts;
  for (std::size_t i = 0; i < samples.size(); i += std::max<std::size_t>(1, stride)) {
    const SymmetryPlane top = climb(samples, kernel, samples[i].plane);
    // Trajectories ending within a bandwidth of a known mode reached that mode.
    int found = -1;
    for (std::size_t m = 0; m < modes.size() && found < 0; ++m) {
      if (planeAngleDeg(modes[m].plane, top) < angle_bandwidth_deg &&
          planeDistanceDifference(modes[m].plane, top) < distance_bandwidth) {
        found = static_cast<int>(m);
      }
    }
    if (found < 0) {
      found = static_cast<int>(modes.size());
      modes.push_back({top, 0.0f});
    }
    mode_of[i] = found;
  }
  // Samples not started from join the nearest mode within the kernel's reach.
  for (std::size_t i = 0; i < samples.size(); ++i) {
    if (mode_of[i] < 0) {
      float best = kCutoff + 1e-6f;
      for (std::size_t m = 0; m < modes.size(); ++m) {
        const float u = kernel.normalisedDistance(modes[m].plane, samples[i].plane);
        if (u < best) {
          best = u;
          mode_of[i] = static_cast<int>(m);
        }
      }
    }
    if (mode_of[i] >= 0) modes[mode_of[i]].support += samples[i].weight;
  }

  std::sort(modes.begin(), modes.end(), [](const Mode& a, const Mode& b) {
    if (a.support != b.support) return a.support > b.support;
    return planeLess(a.plane, b.plane);
  });
  std::vector<SymmetryHypothesis> result;
  for (const Mode& m : modes) {
    if (m.support <= 0.0f) continue;
    SymmetryHypothesis h;
    h.plane = m.plane;
    h.support = static_cast<int>(std::lround(m.support));
    result.push_back(h);
  }
  return result;
}

}  // namespace symmetry_segmentation
