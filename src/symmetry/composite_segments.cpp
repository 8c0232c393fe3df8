// Stage 5c: segments made of two objects split at their concave seam (see the header for why).
#include "symmetry_segmentation/symmetry/composite_segments.h"

#include <algorithm>
#include <iterator>
#include <optional>

namespace symmetry_segmentation {
namespace {

std::size_t intersectionSize(const std::vector<int>& a, const std::vector<int>& b) {
  std::size_t count = 0;
  auto i = a.begin();
  auto j = b.begin();
  while (i != a.end() && j != b.end()) {
    if (*i < *j) {
      ++i;
    } else if (*j < *i) {
      ++j;
    } else {
      ++count;
      ++i;
      ++j;
    }
  }
  return count;
}

bool contains(const std::vector<int>& sorted, int value) {
  return std::binary_search(sorted.begin(), sorted.end(), value);
}

/// Whether parts a and b touch along a seam most of whose links cross a crease.
bool meetAtConcaveSeam(const std::vector<int>& a, const std::vector<int>& b,
                       const std::vector<std::vector<int>>& neighbours, const CreaseTest& crease,
                       const CompositeSegmentParams& params) {
  int links = 0;
  int creased = 0;
  for (int p : a) {
    if (p < 0 || static_cast<std::size_t>(p) >= neighbours.size() || contains(b, p)) continue;
    for (int q : neighbours[p]) {
      if (!contains(b, q) || contains(a, q)) continue;
      ++links;
      creased += crease(p, q) ? 1 : 0;
    }
  }
  return links >= params.min_seam_links && creased >= params.min_crease_fraction * links;
}

/// Whether `plane` mirrors more than the allowed share of `part`'s matched points onto `other`.
bool mirroredOntoOther(const std::vector<int>& part, const std::vector<int>& other, const SymmetryPlane& plane,
                       const ReflectionMatch& match, const CompositeSegmentParams& params) {
  int matched = 0;
  int swapped = 0;
  for (int p : part) {
    if (contains(other, p)) continue;
    const int q = match(p, plane);
    if (q < 0) continue;
    ++matched;
    swapped += (contains(other, q) && !contains(part, q)) ? 1 : 0;
  }
  return matched > 0 && swapped > params.max_swapped_fraction * matched;
}

struct PartPair {
  std::size_t first = 0;
  std::size_t second = 0;
  std::size_t covered = 0;
};

std::optional<PartPair> findSplit(const CandidateSegment& whole, const std::vector<CandidateSegment>& parts,
                                  const std::vector<std::vector<int>>& neighbours, const CreaseTest& crease,
                                  const ReflectionMatch& match, const CompositeSegmentParams& params) {
  const double size = static_cast<double>(whole.points.size());
  std::vector<std::size_t> nested;
  std::vector<std::size_t> inside;  // per nested part: its points within `whole`
  for (std::size_t i = 0; i < parts.size(); ++i) {
    const auto& part = parts[i].points;
    if (part.empty() || part.size() < params.min_part_fraction * size || part.size() >= whole.points.size()) continue;
    const std::size_t common = intersectionSize(part, whole.points);
    if (common < params.min_nested_fraction * part.size()) continue;
    nested.push_back(i);
    inside.push_back(common);
  }
  std::optional<PartPair> best;
  for (std::size_t x = 0; x < nested.size(); ++x) {
    for (std::size_t y = x + 1; y < nested.size(); ++y) {
      const auto& a = parts[nested[x]].points;
      const auto& b = parts[nested[y]].points;
      const std::size_t shared = intersectionSize(a, b);
      if (shared > params.max_part_overlap * std::min(a.size(), b.size())) continue;
      // Points of `whole` in either part (the shared ones counted once, bounded by `shared`).
      const std::size_t covered = inside[x] + inside[y] - std::min(shared, std::min(inside[x], inside[y]));
      if (covered < params.min_coverage * size) continue;
      if (best && covered <= best->covered) continue;
      if (!meetAtConcaveSeam(a, b, neighbours, crease, params)) continue;
      if (mirroredOntoOther(a, b, whole.plane, match, params) || mirroredOntoOther(b, a, whole.plane, match, params)) continue;
      best = PartPair{nested[x], nested[y], covered};
    }
  }
  return best;
}

bool samePoints(const CandidateSegment& a, const CandidateSegment& b) { return a.points == b.points; }

}  // namespace

std::size_t splitCompositeSegments(std::vector<CandidateSegment>& segments, const std::vector<CandidateSegment>& parts,
                                   const std::vector<std::vector<int>>& neighbours, const CreaseTest& crease,
                                   const ReflectionMatch& match, const CompositeSegmentParams& params) {
  std::vector<CandidateSegment> kept;
  std::vector<CandidateSegment> added;
  std::size_t replaced = 0;
  for (auto& segment : segments) {
    const auto split = findSplit(segment, parts, neighbours, crease, match, params);
    if (!split) {
      kept.push_back(std::move(segment));
      continue;
    }
    ++replaced;
    for (std::size_t index : {split->first, split->second}) {
      const CandidateSegment& part = parts[index];
      const auto same = [&](const CandidateSegment& other) { return samePoints(other, part); };
      if (std::none_of(added.begin(), added.end(), same)) added.push_back(part);
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

}  // namespace symmetry_segmentation

