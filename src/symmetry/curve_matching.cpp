// Stage 2, first half: point pairs of two curves that could be mirror images of each other.
// A pair (p, q) proposes the plane bisecting it; the pair survives if p's tangent, reflected
// in that plane, is parallel to q's (paper: within 6 degrees).
#include <algorithm>
#include <cmath>
#include <tuple>

#include "curve_geometry.h"
#include "symmetry_segmentation/symmetry/symmetry_hypotheses.h"
#include "symmetry_segmentation/symmetry/symmetry_plane.h"

namespace symmetry_segmentation {
namespace {

struct Match {
  float cos_error;  // |cos| of reflected vs. matched tangent: larger is better.
  int i, j;
  bool operator<(const Match& other) const {  // Best first; index ties keep it deterministic.
    return std::make_tuple(-cos_error, i, j) < std::make_tuple(-other.cos_error, other.i, other.j);
  }
};

}  // namespace

std::vector<PlaneSample> matchCurveGeometry(const CurveGeometry& a, const CurveGeometry& b, bool same,
                                            const CurvePairParams& params) {
  std::vector<PlaneSample> planes;
  if (a.boxDistance(b) > params.max_match_distance) return planes;
  const float min_squared = params.min_match_distance * params.min_match_distance;
  const float max_squared = params.max_match_distance * params.max_match_distance;
  const float min_cos = std::cos(params.max_tangent_angle_deg * static_cast<float>(M_PI) / 180.0f);

  std::vector<Match> matches;
  const int na = static_cast<int>(a.positions.size());
  const int nb = static_cast<int>(b.positions.size());
  for (int i = 0; i < na; ++i) {
    const Eigen::Vector3f& p = a.positions[i];
    const Eigen::Vector3f& tp = a.tangents[i];
    for (int j = same ? i + 1 : 0; j < nb; ++j) {
      const Eigen::Vector3f d = b.positions[j] - p;
      const float squared = d.squaredNorm();
      if (squared < min_squared || squared > max_squared) continue;
      // Reflection of tp in the bisector plane (normal d / |d|), without normalising d.
      const Eigen::Vector3f reflected = tp - (2.0f * tp.dot(d) / squared) * d;
      const float c = std::fabs(reflected.dot(b.tangents[j]));
      if (c >= min_cos) matches.push_back({c, i, j});
    }
  }
  std::sort(matches.begin(), matches.end());

  // One-to-one: each point takes part in one match, the best one still available.
  std::vector<char> used_a(na, 0), used_b(nb, 0);
  std::vector<char>& used_j = same ? used_a : used_b;
  for (const Match& m : matches) {
    if (used_a[m.i] || used_j[m.j]) continue;
    used_a[m.i] = 1;
    used_j[m.j] = 1;
    PlaneSample sample;
    sample.plane = canonicalPlane(bisectorPlane(a.positions[m.i], b.positions[m.j]));
    planes.push_back(sample);
  }
  return planes;
}

std::vector<PlaneSample> matchCurvePair(const Cloud& cloud, const Curve& a, const Curve& b,
                                        const CurvePairParams& params) {
  const bool same = &a == &b || a.points == b.points;
  return matchCurveGeometry(CurveGeometry(cloud, a), CurveGeometry(cloud, b), same, params);
}

}  // namespace symmetry_segmentation
