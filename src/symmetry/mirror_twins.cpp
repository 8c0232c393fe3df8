// Stage 13, mirror_twins: segments of two mirror-image objects split (see the header for why).
#include "symmetry_segmentation/symmetry/mirror_twins.h"

#include <algorithm>
#include <map>

#include "segment_links.h"
#include "symmetry_segmentation/symmetry/pipeline_state.h"
#include "symmetry_segmentation/symmetry/sorted_indices.h"

namespace symmetry_segmentation {
namespace {

// The pieces of `segment` if they are mirror twins, else nothing.
std::vector<std::vector<int>> twinPieces(const CandidateSegment& segment, const SceneEvidence& evidence,
                                         const MirrorTwinParams& params) {
  const Cloud& cloud = evidence.cloud();
  const std::vector<std::vector<int>>& neighbours = evidence.neighbours();
  const std::vector<int>& points = segment.points;
  int count = 0;
  const std::vector<int> piece = linkedPieceOf(points, neighbours, count);
  if (count < 2) return {};
  std::vector<std::size_t> sizes(count, 0);
  for (int p : piece) ++sizes[p];
  std::vector<int> part(count, -1);
  int parts = 0;
  for (int p = 0; p < count; ++p) {
    if (sizes[p] >= params.min_part_fraction * points.size()) part[p] = parts++;
  }
  if (parts < 2) return {};

  int pairs = 0, free_pairs = 0, self_pairs = 0;
  for (std::size_t k = 0; k < points.size(); ++k) {
    if (part[piece[k]] < 0) continue;
    const int q = evidence.match(points[k], segment.plane);
    const int j = q < 0 ? -1 : positionIn(points, q);
    if (j < 0 || part[piece[j]] < 0) continue;
    if (part[piece[j]] == part[piece[k]]) {
      ++self_pairs;
      continue;
    }
    ++pairs;
    const Eigen::Vector3f middle = 0.5f * (cloud[points[k]].getVector3fMap() + cloud[q].getVector3fMap());
    free_pairs += evidence.observedFree(middle) ? 1 : 0;
  }
  // Two objects mirror onto each other about the plane between them, never onto themselves; a
  // U's uprights do, but its base mirrors onto itself.
  if (pairs < params.min_pairs || free_pairs < params.min_free_fraction * pairs || self_pairs >= pairs) return {};

  // Small pieces join the part they have most links to; unlinked ones the largest part.
  int largest = 0;
  for (int p = 0; p < count; ++p) {
    if (part[p] >= 0 && sizes[p] > sizes[largest]) largest = p;
  }
  std::vector<int> owner(count);
  for (int p = 0; p < count; ++p) {
    if (part[p] >= 0) {
      owner[p] = part[p];
      continue;
    }
    std::map<int, int> links;
    for (std::size_t k = 0; k < points.size(); ++k) {
      if (piece[k] != p) continue;
      for (int q : neighbours[points[k]]) {
        const int j = positionIn(points, q);
        if (j >= 0 && part[piece[j]] >= 0) ++links[part[piece[j]]];
      }
    }
    owner[p] = part[largest];
    int most = 0;
    for (const auto& [target, n] : links) {
      if (n > most) {
        most = n;
        owner[p] = target;
      }
    }
  }
  std::vector<std::vector<int>> result(parts);
  for (std::size_t k = 0; k < points.size(); ++k) result[owner[piece[k]]].push_back(points[k]);
  return result;
}

}  // namespace

std::size_t splitMirrorTwins(std::vector<CandidateSegment>& segments, const SceneEvidence& evidence,
                             const MirrorTwinParams& params) {
  std::size_t split = 0;
  const std::size_t original = segments.size();
  for (std::size_t i = 0; i < original; ++i) {
    std::vector<std::vector<int>> pieces = twinPieces(segments[i], evidence, params);
    if (pieces.empty()) continue;
    ++split;
    const SymmetryPlane plane = segments[i].plane;
    for (std::size_t p = 0; p < pieces.size(); ++p) {
      CandidateSegment piece;
      piece.plane = plane;
      piece.scores = evidence.scores(pieces[p], plane);
      piece.points = std::move(pieces[p]);
      if (p == 0) segments[i] = std::move(piece);
      else segments.push_back(std::move(piece));
    }
  }
  return split;
}

void MirrorTwinStage::run(PipelineState& state) const {
  state.count("split", splitMirrorTwins(state.segments, *state.evidence, params_));
}

}  // namespace symmetry_segmentation
