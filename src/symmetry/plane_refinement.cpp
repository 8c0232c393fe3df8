// Stage 5, refine: the plane that best maps a segment onto itself. This is point-to-plane ICP between
// the segment and its reflection, with the motion constrained to be a reflection: each
// iteration mirrors the segment about the current plane, pairs every mirrored point one-to-one
// with its nearest compatible segment point, and solves a Gauss-Newton step for the plane's
// three degrees of freedom (normal direction and offset) minimising the point-to-plane
// distances. A free rigid ICP followed by a plane re-fit needs six unknowns, converges more
// slowly, and the re-fit from noisy point pairs biases the offset by millimetres that then show
// as reflections into free space.
#include "symmetry_segmentation/symmetry/plane_refinement.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include <Eigen/Cholesky>

#include "symmetry_segmentation/parallel_for.h"
#include "symmetry_segmentation/symmetry/pipeline_state.h"
#include "symmetry_segmentation/symmetry/point_grid.h"
#include "symmetry_segmentation/symmetry/symmetric_graph_cut.h"
#include "symmetry_segmentation/symmetry/symmetry_plane.h"

namespace symmetry_segmentation {
namespace {

// Fixed: a step this small has converged (m, and radians of the normal).
constexpr float kConvergedStep = 1e-5f;
// Fixed, a speed-up only: most mirrored points land within a voxel of their counterpart, so the
// grid has 1 cm cells and that radius is searched first (the nearest within it is the nearest).
constexpr float kNearRadius = 0.01f;

struct Match {
  int source = -1;
  float squared_distance = std::numeric_limits<float>::max();
};

/// Index and squared distance of the grid point nearest to `query` within `radius` whose normal
/// is compatible with `normal`, or -1. (On a thin wall the nearest voxel is often the other
/// side's, facing the opposite way.)
int nearestCompatible(const PointGrid& grid, const Cloud& points, const Eigen::Vector3f& query,
                      const Eigen::Vector3f& normal, float radius, float min_normal_cos, float& squared_distance) {
  int nearest = -1;
  squared_distance = std::numeric_limits<float>::max();
  for (const float r : {std::min(kNearRadius, radius), radius}) {
    grid.forEachWithin(query, r, [&](int index, float squared) {
      if (squared < squared_distance && normal.dot(points.points[index].getNormalVector3fMap()) >= min_normal_cos) {
        squared_distance = squared;
        nearest = index;
      }
    });
    if (nearest >= 0) break;
  }
  return nearest;
}

/// Two unit vectors spanning the plane perpendicular to n.
void tangentBasis(const Eigen::Vector3f& n, Eigen::Vector3f& u, Eigen::Vector3f& v) {
  const Eigen::Vector3f helper = std::fabs(n.x()) < 0.9f ? Eigen::Vector3f::UnitX() : Eigen::Vector3f::UnitY();
  u = n.cross(helper).normalized();
  v = n.cross(u);
}

}  // namespace

SymmetryPlane refinePlane(const Cloud& cloud, const std::vector<int>& segment, const SymmetryPlane& plane,
                          const SymmetryRefinementParams& refinement) {
  if (static_cast<int>(segment.size()) < refinement.min_points) return plane;
  auto points = std::make_shared<Cloud>();
  points->reserve(segment.size());
  for (int index : segment) points->push_back(cloud.points[index]);
  // A grid answers these fixed-radius queries faster than a kd-tree (see point_grid.h).
  const PointGrid grid(*points, kNearRadius);

  const int n = static_cast<int>(points->size());
  const float max_squared = refinement.icp_max_correspondence * refinement.icp_max_correspondence;
  SymmetryPlane current = plane;
  std::vector<Match> best_for_target(n);
  std::vector<int> target_of(n);
  for (int iteration = 0; iteration < refinement.icp_iterations; ++iteration) {
    // Nearest compatible counterpart of each mirrored point; one-to-one: a target keeps only its
    // closest source.
    std::fill(best_for_target.begin(), best_for_target.end(), Match());
    for (int i = 0; i < n; ++i) {
      target_of[i] = -1;
      const PointT& p = points->points[i];
      float squared = 0.0f;
      const int target = nearestCompatible(grid, *points, reflectPoint(current, p.getVector3fMap()),
                                           reflectDirection(current, p.getNormalVector3fMap()),
                                           refinement.icp_max_correspondence, refinement.min_normal_cos, squared);
      if (target < 0 || squared > max_squared) continue;
      Match& match = best_for_target[target];
      if (squared < match.squared_distance) match = {i, squared};
    }
    int matched = 0;
    for (int t = 0; t < n; ++t) {
      if (best_for_target[t].source >= 0) {
        target_of[best_for_target[t].source] = t;
        ++matched;
      }
    }
    // Most of the mirrored segment must find counterparts for the plane to be a symmetry of it.
    if (matched < refinement.min_matched_fraction * static_cast<float>(n)) return plane;

    // Gauss-Newton on (a, b, delta_d) with normal n + a u + b v, residual
    // r = n_q . (M(p) - q), M(p) = p - 2 (n . p + d) n.
    Eigen::Vector3f u, v;
    tangentBasis(current.normal, u, v);
    Eigen::Matrix3f jtj = Eigen::Matrix3f::Zero();
    Eigen::Vector3f jtr = Eigen::Vector3f::Zero();
    for (int i = 0; i < n; ++i) {
      if (target_of[i] < 0) continue;
      const Eigen::Vector3f p = points->points[i].getVector3fMap();
      const PointT& target = points->points[target_of[i]];
      const Eigen::Vector3f q = target.getVector3fMap();
      const Eigen::Vector3f nq = target.getNormalVector3fMap();
      const float s = signedDistance(current, p);
      const float residual = nq.dot(reflectPoint(current, p) - q);
      const float normal_dot = nq.dot(current.normal);
      const Eigen::Vector3f jacobian(-2.0f * (u.dot(p) * normal_dot + s * nq.dot(u)),
                                     -2.0f * (v.dot(p) * normal_dot + s * nq.dot(v)), -2.0f * normal_dot);
      jtj += jacobian * jacobian.transpose();
      jtr += jacobian * residual;
    }
    // A small damping keeps directions the segment does not constrain (a flat patch) still.
    jtj += 1e-6f * Eigen::Matrix3f::Identity() * std::max(1.0f, jtj.trace());
    const Eigen::Vector3f step = -jtj.ldlt().solve(jtr);
    if (!step.allFinite()) return plane;
    current.normal = (current.normal + step.x() * u + step.y() * v).normalized();
    current.distance += step.z();
    if (step.norm() < kConvergedStep) break;
  }
  current = canonicalPlane(current);
  // Turned further, it found another symmetry, not a better estimate of this one.
  if (planeAngleDeg(current, plane) > refinement.max_turn_deg) return plane;
  return current;
}

void RefineStage::run(PipelineState& state) const {
  const std::size_t first = state.refined;
  std::vector<char> recut(state.candidates.size() - first, 0);  // per index: no shared counter
  parallelFor(recut.size(), state.threads, [&](std::size_t k) {
    const std::size_t i = first + k;
    CandidateSegment& candidate = state.candidates[i];
    if (static_cast<int>(candidate.points.size()) < filter_.min_segment_points) return;
    const SymmetryPlane before = candidate.plane;
    candidate.plane = refinePlane(*state.cloud, candidate.points, candidate.plane, params_);
    // The same plane would give the same cut.
    if (candidate.plane.normal == before.normal && candidate.plane.distance == before.distance) return;
    candidate.points = state.graph->segment(candidate.plane, state.hypotheses[i].anchor);
    candidate.scores = state.evidence->scores(candidate.points, candidate.plane);
    recut[k] = 1;
  });
  state.refined = state.candidates.size();
  state.count("recuts", static_cast<std::size_t>(std::count(recut.begin(), recut.end(), 1)));
}

}  // namespace symmetry_segmentation
