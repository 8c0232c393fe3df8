// Stage 9, occluder_gaps: planes across the hidden gap between two pieces of one object (see the header).
#include "symmetry_segmentation/symmetry/occluder_gaps.h"

#include <algorithm>
#include <stdexcept>

#include <cmath>

#include <Eigen/Geometry>
#include <pcl/common/centroid.h>

#include "color_lab.h"
#include "symmetry_segmentation/parallel_for.h"
#include "symmetry_segmentation/quantile.h"
#include "symmetry_segmentation/symmetry/duplicate_segments.h"
#include "symmetry_segmentation/symmetry/pipeline_state.h"
#include "symmetry_segmentation/symmetry/scene_evidence.h"
#include "symmetry_segmentation/symmetry/sorted_indices.h"
#include "symmetry_segmentation/symmetry/symmetric_graph_cut.h"
#include "symmetry_segmentation/symmetry/symmetry_plane.h"

namespace symmetry_segmentation {
namespace {

// Share of a piece's points left out at its ends: a stray point does not move an end.
constexpr float kEndTrim = 0.02f;

Eigen::Vector3f centroidOf(const Cloud& cloud, const std::vector<int>& points) {
  Eigen::Vector4f centroid;
  pcl::compute3DCentroid(cloud, points, centroid);
  return centroid.head<3>();
}

/// The kEndTrim and 1 - kEndTrim quantiles of the points' positions along `axis`.
std::pair<float, float> extentAlong(const Cloud& cloud, const std::vector<int>& points, const Eigen::Vector3f& axis) {
  std::vector<float> along;
  along.reserve(points.size());
  for (int i : points) along.push_back(axis.dot(cloud[i].getVector3fMap()));
  return trimmedRange(along, kEndTrim);
}

/// `plane` turned by `angle_deg` about `up`, halfway between the outer ends of both pieces along its new normal.
SymmetryHypothesis turnedAbout(const SymmetryHypothesis& hypothesis, const Cloud& cloud, const std::vector<int>& first,
                               const std::vector<int>& second, const Eigen::Vector3f& up, float angle_deg) {
  SymmetryHypothesis turned = hypothesis;
  const Eigen::Vector3f normal =
      (Eigen::AngleAxisf(angle_deg * static_cast<float>(M_PI) / 180.0f, up) * hypothesis.plane.normal).normalized();
  const auto [first_low, first_high] = extentAlong(cloud, first, normal);
  const auto [second_low, second_high] = extentAlong(cloud, second, normal);
  turned.plane.normal = normal;
  turned.plane.distance = -0.5f * (std::min(first_low, second_low) + std::max(first_high, second_high));
  turned.plane = canonicalPlane(turned.plane);
  return turned;
}

}  // namespace

float sharedColorShare(const Cloud& cloud, const std::vector<int>& points, const std::vector<int>& other,
                       float max_difference) {
  if (points.empty() || other.empty()) return 0.0f;
  constexpr std::size_t kMaxPalette = 256;  // colours of `other` compared against: bounds the cost
  const std::size_t stride = (other.size() + kMaxPalette - 1) / kMaxPalette;
  std::vector<Eigen::Vector3f> palette;
  for (std::size_t k = 0; k < other.size(); k += stride) palette.push_back(toLab(cloud[other[k]]));
  std::size_t shared = 0;
  for (int i : points) {
    const Eigen::Vector3f lab = toLab(cloud[i]);
    shared += std::any_of(palette.begin(), palette.end(),
                          [&](const Eigen::Vector3f& c) { return colorDifference(lab, c) < max_difference; });
  }
  return static_cast<float>(shared) / static_cast<float>(points.size());
}

std::vector<SymmetryHypothesis> occluderGapHypothesis(const Cloud& cloud, const std::vector<int>& first,
                                                      const std::vector<int>& second, const OccupancyMap& occupancy,
                                                      const OccluderGapParams& params) {
  if (first.size() < 3 || second.size() < 3) return {};
  const Eigen::Vector3f first_centre = centroidOf(cloud, first);
  const Eigen::Vector3f second_centre = centroidOf(cloud, second);
  const Eigen::Vector3f between = second_centre - first_centre;
  if (between.norm() < 1e-6f) return {};
  const Eigen::Vector3f axis = between.normalized();
  const auto [first_low, first_high] = extentAlong(cloud, first, axis);
  const auto [second_low, second_high] = extentAlong(cloud, second, axis);
  const float gap = second_low - first_high;
  if (gap < params.min_gap || second_high - first_low > params.max_span) return {};
  // The middle of the gap, at the pieces' mean position across the axis: seen through means two
  // objects; hidden (behind the occluder, or never observed) leaves it to the cut.
  const Eigen::Vector3f middle = 0.5f * (first_centre + second_centre) +
                                 axis * (0.5f * (first_high + second_low) - axis.dot(0.5f * (first_centre + second_centre)));
  if (occupancy.classify(middle) == Occupancy::Free) return {};
  SymmetryHypothesis hypothesis;
  hypothesis.plane.normal = axis;
  hypothesis.plane.distance = -0.5f * (first_low + second_high);
  hypothesis.plane = canonicalPlane(hypothesis.plane);
  hypothesis.anchor = first;
  hypothesis.anchor.insert(hypothesis.anchor.end(), second.begin(), second.end());
  std::sort(hypothesis.anchor.begin(), hypothesis.anchor.end());
  return {hypothesis};
}

void OccluderGapStage::run(PipelineState& state) const {
  // Hypotheses not cut yet would be paired with this stage's candidates (the stage list is
  // checked for this; a hand-made state may still get here).
  if (state.candidates.size() != state.hypotheses.size()) {
    throw std::logic_error("occluder_gaps: every hypothesis must be cut before it runs");
  }
  // The passing candidates, each point set once (several planes often cut the same piece).
  std::vector<const CandidateSegment*> pieces;
  for (const CandidateSegment& candidate : state.candidates) {
    if (!passesFilter(candidate, filter_)) continue;
    const bool seen = std::any_of(pieces.begin(), pieces.end(), [&](const CandidateSegment* piece) {
      return overlapOfSmaller(piece->points, candidate.points) > dedup_.max_overlap;
    });
    if (!seen) pieces.push_back(&candidate);
  }
  // Per pair the plane across the gap, and the same turned about the up direction: the line
  // between the pieces' centroids is the object's axis only when both show the same share of its
  // width, and a box lying askew under another is seen in pieces that do not (OSD learn18).
  struct PlaneAcross {
    SymmetryHypothesis hypothesis;
    const CandidateSegment* first;
    const CandidateSegment* second;
  };
  std::vector<PlaneAcross> planes;
  std::vector<std::size_t> first_plane_of_pair;  // a pair's planes are consecutive from here
  for (std::size_t a = 0; a < pieces.size(); ++a) {
    for (std::size_t b = a + 1; b < pieces.size(); ++b) {
      if (overlapOfSmaller(pieces[a]->points, pieces[b]->points) > 0.0f) continue;
      if (state.has_color && params_.min_shared_color > 0.0f &&
          (sharedColorShare(*state.cloud, pieces[a]->points, pieces[b]->points, params_.max_color_difference) <
               params_.min_shared_color ||
           sharedColorShare(*state.cloud, pieces[b]->points, pieces[a]->points, params_.max_color_difference) <
               params_.min_shared_color)) {
        continue;
      }
      for (auto& hypothesis :
           occluderGapHypothesis(*state.cloud, pieces[a]->points, pieces[b]->points, *state.occupancy, params_)) {
        first_plane_of_pair.push_back(planes.size());
        planes.push_back({std::move(hypothesis), pieces[a], pieces[b]});
        if (!state.up || params_.turn_step_deg <= 0.0f) continue;
        const SymmetryHypothesis across = planes.back().hypothesis;  // a copy: planes grows
        for (float angle = params_.turn_step_deg; angle <= params_.max_turn_deg + 1e-3f; angle += params_.turn_step_deg) {
          for (const float signed_angle : {-angle, angle}) {
            planes.push_back({turnedAbout(across, *state.cloud, pieces[a]->points, pieces[b]->points, *state.up, signed_angle),
                             pieces[a], pieces[b]});
          }
        }
      }
    }
  }
  first_plane_of_pair.push_back(planes.size());
  // Cut here rather than in a later cut stage: only a cut that joins both pieces is a candidate.
  // Any other would be one more piece for the stages that split segments into found parts.
  std::vector<CandidateSegment> cuts(planes.size());
  std::vector<float> coverage(planes.size(), 0.0f);  // of the piece it covers less
  parallelFor(planes.size(), state.threads, [&](std::size_t k) {
    CandidateSegment& cut = cuts[k];
    cut.plane = planes[k].hypothesis.plane;
    cut.points = state.graph->segment(cut.plane, planes[k].hypothesis.anchor);
    const auto share = [&](const CandidateSegment* piece) {
      return static_cast<float>(intersectionSize(cut.points, piece->points)) / static_cast<float>(piece->points.size());
    };
    coverage[k] = std::min(share(planes[k].first), share(planes[k].second));
  });
  // Every plane whose cut takes enough of both pieces is a candidate: the one taking most is not
  // always the best segment (learn18), so refine and dedup choose, as for any other candidates.
  std::size_t joined = 0;
  for (std::size_t k = 0; k < planes.size(); ++k) {
    if (coverage[k] < params_.min_piece_coverage) continue;
    // Hypotheses and candidates stay index-aligned (candidates[i] is the cut of hypotheses[i]).
    cuts[k].scores = state.evidence->scores(cuts[k].points, cuts[k].plane);
    state.hypotheses.push_back(std::move(planes[k].hypothesis));
    state.candidates.push_back(std::move(cuts[k]));
    ++joined;
  }
  state.count("pairs", first_plane_of_pair.size() - 1);
  state.count("cuts", planes.size());
  state.count("joined", joined);
}

}  // namespace symmetry_segmentation
