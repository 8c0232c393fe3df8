// Stage 14, composites: segments made of two objects split at their concave seam (see the header for why).
#include "symmetry_segmentation/symmetry/composite_segments.h"

#include <algorithm>
#include <cstdint>
#include <iterator>
#include <optional>
#include <utility>

#include "color_lab.h"
#include "symmetry_segmentation/symmetry/color_histogram.h"
#include "symmetry_segmentation/symmetry/pipeline_state.h"
#include "symmetry_segmentation/symmetry/sorted_indices.h"

namespace symmetry_segmentation {
namespace {

/// The evidence's concave creases at one angle.
class Creases {
 public:
  Creases(const SceneEvidence& evidence, float angle_deg) : evidence_(evidence), angle_deg_(angle_deg) {}
  bool operator()(int a, int b) const { return evidence_.concaveCrease(a, b, angle_deg_); }

 private:
  const SceneEvidence& evidence_;
  float angle_deg_;
};

/// The smoothness graph's links, with scratch marks on its points: the seam walks ask, link by
/// link, which part a point is in, and a pair of parts is marked and cleared again in the time
/// of a look-up per point (a segment is tried against hundreds of pairs on a cluttered frame).
class Links {
 public:
  static constexpr std::uint8_t kInA = 1, kInB = 2, kInWhole = 4, kReached = 8;

  explicit Links(const std::vector<std::vector<int>>& neighbours)
      : neighbours_(neighbours), marks_(neighbours.size(), 0) {}
  bool valid(int p) const { return p >= 0 && static_cast<std::size_t>(p) < neighbours_.size(); }
  const std::vector<int>& of(int p) const { return neighbours_[p]; }
  bool has(int p, std::uint8_t mark) const { return valid(p) && (marks_[p] & mark) != 0; }
  void set(int p, std::uint8_t mark) const {
    if (valid(p)) marks_[p] |= mark;
  }
  void set(const std::vector<int>& points, std::uint8_t mark) const {
    for (int p : points) set(p, mark);
  }
  void clear(const std::vector<int>& points, std::uint8_t mark) const {
    for (int p : points) {
      if (valid(p)) marks_[p] &= static_cast<std::uint8_t>(~mark);
    }
  }

 private:
  const std::vector<std::vector<int>>& neighbours_;
  mutable std::vector<std::uint8_t> marks_;
};

/// `points` marked `mark` for its lifetime.
class Marked {
 public:
  Marked(const Links& links, const std::vector<int>& points, std::uint8_t mark)
      : links_(links), points_(points), mark_(mark) {
    links_.set(points_, mark_);
  }
  ~Marked() { links_.clear(points_, mark_); }
  Marked(const Marked&) = delete;
  Marked& operator=(const Marked&) = delete;

 private:
  const Links& links_;
  const std::vector<int>& points_;
  std::uint8_t mark_;
};

/// Whether parts a and b are apart (fewer than min_seam_links links between them) or meet at a
/// seam at least `min_crease_fraction` of whose links cross a crease.
bool apartOrCreased(const std::vector<int>& a, const std::vector<int>& b, const Links& links, const Creases& crease,
                    float min_crease_fraction, const CompositeSegmentParams& params) {
  const Marked in_a(links, a, Links::kInA);
  const Marked in_b(links, b, Links::kInB);
  int seam_links = 0;
  int creased = 0;
  for (int p : a) {
    if (!links.valid(p) || links.has(p, Links::kInB)) continue;
    for (int q : links.of(p)) {
      if (!links.has(q, Links::kInB) || links.has(q, Links::kInA)) continue;
      ++seam_links;
      creased += crease(p, q) ? 1 : 0;
    }
  }
  return seam_links < params.min_seam_links || creased >= min_crease_fraction * seam_links;
}

/// Whether a path from `a` to `b` runs within `whole` over links that cross no crease. Two
/// objects touch at creases; parts of one object that each have a symmetry of their own (an
/// L-shaped block's slab and upright) meet at a crease too, but also run on into each other
/// somewhere over a flat face or a convex edge, directly or through a corner neither part took.
/// `crease` here is the stricter joined_angle_deg: normals smoothed over a few centimetres turn
/// through a concave corner in steps of ~15 deg at 1 cm, so a path at crease_angle_deg slips
/// from one stacked box onto the other through the seam it should stop at.
bool joinedWithoutCrease(const std::vector<int>& whole, const std::vector<int>& a, const std::vector<int>& b,
                         const Links& links, const Creases& crease) {
  const Marked in_whole(links, whole, Links::kInWhole);
  const Marked in_b(links, b, Links::kInB);
  std::vector<int> reached;
  for (int p : a) {
    if (!links.has(p, Links::kInWhole) || links.has(p, Links::kInB) || links.has(p, Links::kReached)) continue;
    links.set(p, Links::kReached);
    reached.push_back(p);
  }
  std::vector<int> frontier = reached;
  bool joined = false;
  while (!frontier.empty() && !joined) {
    const int p = frontier.back();
    frontier.pop_back();
    for (int q : links.of(p)) {
      if (!links.has(q, Links::kInWhole) || crease(p, q)) continue;
      if (links.has(q, Links::kInB)) {
        joined = true;
        break;
      }
      if (links.has(q, Links::kReached)) continue;
      links.set(q, Links::kReached);
      reached.push_back(q);
      frontier.push_back(q);
    }
  }
  links.clear(reached, Links::kReached);
  return joined;
}

/// Whether `plane` mirrors more than the allowed share of `part`'s matched points onto `other`.
bool mirroredOntoOther(const std::vector<int>& part, const std::vector<int>& other, const SymmetryPlane& plane,
                       const SceneEvidence& evidence, const CompositeSegmentParams& params) {
  int matched = 0;
  int swapped = 0;
  for (int p : part) {
    if (contains(other, p)) continue;
    const int q = evidence.match(p, plane);
    if (q < 0) continue;
    ++matched;
    swapped += (contains(other, q) && !contains(part, q)) ? 1 : 0;
  }
  return matched > 0 && swapped > params.max_swapped_fraction * matched;
}

/// The mean colour (CIELAB) of the points of `part` not in `other`.
Eigen::Vector3f meanColorApart(const std::vector<int>& part, const std::vector<int>& other, const Cloud& cloud) {
  Eigen::Vector3f sum = Eigen::Vector3f::Zero();
  int count = 0;
  for (int p : part) {
    if (contains(other, p)) continue;
    sum += toLab(cloud[p]);
    ++count;
  }
  return count > 0 ? Eigen::Vector3f(sum / static_cast<float>(count)) : sum;
}

/// Whether parts a and b look like one object's, in a cloud with colour: one colour (their means
/// closer than min_color_difference), or one print (sharing min_color_overlap of their colours;
/// an L-shaped block's printed slab and upright differ in mean as much as two objects do).
bool oneColor(const std::vector<int>& a, const std::vector<int>& b, const SceneEvidence& evidence,
              const CompositeSegmentParams& params) {
  if (!params.use_color) return false;
  const Cloud& cloud = evidence.cloud();
  if (params.min_color_difference > 0.0f &&
      colorDifference(meanColorApart(a, b, cloud), meanColorApart(b, a, cloud)) < params.min_color_difference) {
    return true;
  }
  return params.min_color_overlap > 0.0f && colorOverlap(cloud, a, b) >= params.min_color_overlap;
}

/// Whether parts a and b of `whole` are two objects: apart or meeting at a concave seam (at least
/// `min_crease_fraction` of their links creased), each mirrored onto itself by `whole`'s plane,
/// not of one colour.
bool twoObjects(const CandidateSegment& whole, const std::vector<int>& a, const std::vector<int>& b,
                float min_crease_fraction, const Links& links, const Creases& crease,
                const SceneEvidence& evidence, const CompositeSegmentParams& params) {
  return apartOrCreased(a, b, links, crease, min_crease_fraction, params) &&
         !mirroredOntoOther(a, b, whole.plane, evidence, params) && !mirroredOntoOther(b, a, whole.plane, evidence, params) &&
         !oneColor(a, b, evidence, params);  // last: the colour means convert every point
}

/// The points of `whole` in `a` or `b`.
std::vector<int> unionWithin(const std::vector<int>& whole, const std::vector<int>& a, const std::vector<int>& b) {
  return intersection(whole, setUnion(a, b));
}

/// An object seen in two pieces either side of another, in front of it and centred on the same
/// plane: the cut of that plane takes all three, each piece is found alone (never the occluder,
/// which is seen whole only with them), and the pieces are each other's mirror images. Their
/// union is one object and the rest of `whole` the other, both kept on `whole`'s plane.
/// `pieces`: the parts lying within `whole` (any size up to max_part_fraction of it).
std::optional<std::pair<CandidateSegment, CandidateSegment>> splitAtMirroredPieces(
    const CandidateSegment& whole, const std::vector<CandidateSegment>& parts, const std::vector<std::size_t>& pieces,
    const Links& links, const Creases& crease, const SceneEvidence& evidence,
    const CompositeSegmentParams& params) {
  const double size = static_cast<double>(whole.points.size());
  std::optional<std::pair<CandidateSegment, CandidateSegment>> best;
  for (std::size_t x = 0; x < pieces.size(); ++x) {
    for (std::size_t y = x + 1; y < pieces.size(); ++y) {
      const auto& a = parts[pieces[x]].points;
      const auto& b = parts[pieces[y]].points;
      if (intersectionSize(a, b) > params.max_part_overlap * std::min(a.size(), b.size())) continue;
      std::vector<int> object = unionWithin(whole.points, a, b);
      // Each piece a fair share of the object, the object a fair share of `whole`.
      if (std::min(a.size(), b.size()) < params.min_part_fraction * object.size() ||
          object.size() < params.min_part_fraction * size || object.size() > params.max_part_fraction * size) {
        continue;
      }
      if (best && object.size() <= best->first.points.size()) continue;
      if (!mirroredOntoOther(a, b, whole.plane, evidence, params) || !mirroredOntoOther(b, a, whole.plane, evidence, params)) {
        continue;
      }
      std::vector<int> rest = difference(whole.points, object);
      if (!twoObjects(whole, object, rest, params.min_rest_crease_fraction, links, crease, evidence, params)) continue;
      CandidateSegment first, second;
      first.points = std::move(object);
      second.points = std::move(rest);
      first.plane = second.plane = whole.plane;
      best = std::make_pair(std::move(first), std::move(second));
    }
  }
  if (!best) return std::nullopt;
  best->first.scores = evidence.scores(best->first.points, best->first.plane);
  best->second.scores = evidence.scores(best->second.points, best->second.plane);
  return best;
}

/// The two objects `whole` is made of: two segments of `parts` covering it, else one segment of
/// `parts` and the rest of `whole` (which keeps `whole`'s plane).
std::optional<std::pair<CandidateSegment, CandidateSegment>> findSplit(
    const CandidateSegment& whole, const std::vector<CandidateSegment>& parts,
    const Links& links, const Creases& crease, const Creases& joined_crease,
    const SceneEvidence& evidence, const CompositeSegmentParams& params) {
  const double size = static_cast<double>(whole.points.size());
  std::vector<std::size_t> within;  // parts lying within `whole`, of any size up to the largest part
  std::vector<std::size_t> nested;  // those of a part's size
  std::vector<std::size_t> inside;  // per nested part: its points within `whole`
  for (std::size_t i = 0; i < parts.size(); ++i) {
    const auto& part = parts[i].points;
    if (part.empty() || part.size() > params.max_part_fraction * size) continue;
    const std::size_t common = intersectionSize(part, whole.points);
    if (common < params.min_nested_fraction * part.size()) continue;
    within.push_back(i);
    if (part.size() < params.min_part_fraction * size) continue;
    nested.push_back(i);
    inside.push_back(common);
  }
  // Both objects found alone: the pair covering most of `whole`.
  std::optional<std::pair<std::size_t, std::size_t>> best_pair;
  std::size_t best_covered = 0;
  for (std::size_t x = 0; x < nested.size(); ++x) {
    for (std::size_t y = x + 1; y < nested.size(); ++y) {
      const auto& a = parts[nested[x]].points;
      const auto& b = parts[nested[y]].points;
      const std::size_t shared = intersectionSize(a, b);
      if (shared > params.max_part_overlap * std::min(a.size(), b.size())) continue;
      // Points of `whole` in either part (the shared ones counted once, bounded by `shared`).
      const std::size_t covered = inside[x] + inside[y] - std::min(shared, std::min(inside[x], inside[y]));
      if (covered < params.min_coverage * size || covered <= best_covered) continue;
      // The seam tests first: the mirror tests reflect every point of both parts.
      if (!apartOrCreased(a, b, links, crease, params.min_crease_fraction, params)) continue;
      if (joinedWithoutCrease(whole.points, a, b, links, joined_crease)) continue;
      if (!twoObjects(whole, a, b, params.min_crease_fraction, links, crease, evidence, params)) continue;
      best_pair = std::make_pair(nested[x], nested[y]);
      best_covered = covered;
    }
  }
  if (best_pair) return std::make_pair(parts[best_pair->first], parts[best_pair->second]);
  // One object found alone; the rest of `whole` is the other (an object seen in pieces around
  // the first, which is never found whole by itself). The largest such part.
  std::optional<CandidateSegment> best_rest;
  std::size_t best_part = 0;
  for (std::size_t x = 0; x < nested.size(); ++x) {
    const auto& a = parts[nested[x]].points;
    if (best_rest && a.size() <= parts[best_part].points.size()) continue;
    std::vector<int> rest = difference(whole.points, a);
    if (rest.size() < params.min_part_fraction * size) continue;
    // Not found alone, a rest may belong to the part (the upright of an L-shaped block, whose
    // faces run on flush across the seam): it counts only if apart or met at creases alone.
    if (!twoObjects(whole, a, rest, params.min_rest_crease_fraction, links, crease, evidence, params)) continue;
    CandidateSegment other;
    other.points = std::move(rest);
    other.plane = whole.plane;
    best_rest = std::move(other);
    best_part = nested[x];
  }
  if (best_rest) {
    best_rest->scores = evidence.scores(best_rest->points, best_rest->plane);
    return std::make_pair(parts[best_part], std::move(*best_rest));
  }
  return splitAtMirroredPieces(whole, parts, within, links, crease, evidence, params);
}

bool samePoints(const CandidateSegment& a, const CandidateSegment& b) { return a.points == b.points; }

}  // namespace

std::size_t splitCompositeSegments(std::vector<CandidateSegment>& segments, const std::vector<CandidateSegment>& parts,
                                   const SceneEvidence& evidence, const CompositeSegmentParams& params) {
  const Links links(evidence.neighbours());
  const Creases crease(evidence, params.crease_angle_deg);
  const Creases joined_crease(evidence, params.joined_angle_deg);
  std::vector<CandidateSegment> kept;
  std::vector<CandidateSegment> added;
  std::size_t replaced = 0;
  for (auto& segment : segments) {
    auto split = findSplit(segment, parts, links, crease, joined_crease, evidence, params);
    if (!split) {
      kept.push_back(std::move(segment));
      continue;
    }
    ++replaced;
    for (CandidateSegment* part : {&split->first, &split->second}) {
      const auto same = [&](const CandidateSegment& other) { return samePoints(other, *part); };
      if (std::none_of(added.begin(), added.end(), same)) added.push_back(std::move(*part));
    }
  }
  // A part that is itself among the remaining segments is not added twice.
  for (auto& part : added) {
    const auto same = [&](const CandidateSegment& other) { return samePoints(other, part); };
    if (std::none_of(kept.begin(), kept.end(), same)) kept.push_back(std::move(part));
  }
  segments = std::move(kept);
  return replaced;
}

void CompositeStage::run(PipelineState& state) const {
  // Parts: the segments and every candidate the cuts made. An object found alone need not pass
  // the filter by itself (a box on a box, each mirrored by the plane they share) to show where a
  // segment of two objects parts; the checks on the seam and the plane still decide.
  std::vector<CandidateSegment> parts = state.segments;
  for (const CandidateSegment& candidate : state.candidates) {
    if (!candidate.points.empty()) parts.push_back(candidate);
  }
  CompositeSegmentParams params = params_;
  params.use_color = state.has_color;
  state.count("split", splitCompositeSegments(state.segments, parts, *state.evidence, params));
}

}  // namespace symmetry_segmentation
