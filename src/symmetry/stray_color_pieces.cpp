// Optional stage stray_color_pieces: strips of a neighbour's colour moved to that neighbour (see the header for why).
#include "symmetry_segmentation/symmetry/stray_color_pieces.h"

#include <algorithm>
#include <iterator>
#include <map>

#include "color_lab.h"
#include "disjoint_sets.h"
#include "symmetry_segmentation/symmetry/pipeline_state.h"
#include "symmetry_segmentation/symmetry/sorted_indices.h"

namespace symmetry_segmentation {
namespace {

struct ColorRegions {
  std::vector<std::vector<int>> members;   // positions per region
  std::vector<Eigen::Vector3f> mean;       // Lab per region
  int dominant = -1;
};

ColorRegions colorRegionsOf(const std::vector<int>& points, const Cloud& cloud,
                            const std::vector<std::vector<int>>& neighbours, float max_difference) {
  std::vector<Eigen::Vector3f> lab(points.size());
  for (std::size_t j = 0; j < points.size(); ++j) lab[j] = toLab(cloud[points[j]]);
  DisjointSets sets = colorRegions(points, lab, neighbours, max_difference);
  ColorRegions result;
  std::map<int, int> index_of_root;
  for (std::size_t j = 0; j < points.size(); ++j) {
    const int root = sets.find(static_cast<int>(j));
    const auto it = index_of_root.emplace(root, static_cast<int>(index_of_root.size())).first;
    if (it->second == static_cast<int>(result.members.size())) {
      result.members.emplace_back();
      result.mean.push_back(Eigen::Vector3f::Zero());
    }
    result.members[it->second].push_back(static_cast<int>(j));
    result.mean[it->second] += lab[j];
  }
  for (std::size_t r = 0; r < result.members.size(); ++r) {
    result.mean[r] /= static_cast<float>(result.members[r].size());
    if (result.dominant < 0 || result.members[r].size() > result.members[result.dominant].size()) {
      result.dominant = static_cast<int>(r);
    }
  }
  return result;
}

}  // namespace

std::size_t moveStrayColorPieces(std::vector<CandidateSegment>& segments, const Cloud& cloud,
                                 const std::vector<std::vector<int>>& neighbours, const StrayColorParams& params) {
  const float max_color_difference = params.max_color_difference;
  std::vector<ColorRegions> regions;
  std::vector<int> owner(cloud.size(), -1);
  for (std::size_t s = 0; s < segments.size(); ++s) {
    regions.push_back(colorRegionsOf(segments[s].points, cloud, neighbours, max_color_difference));
    for (int p : segments[s].points) {
      if (owner[p] < 0) owner[p] = static_cast<int>(s);
    }
  }
  auto uniform = [&](std::size_t s) {
    const ColorRegions& r = regions[s];
    return r.dominant >= 0 && r.members[r.dominant].size() >= params.min_dominant_share * segments[s].points.size();
  };
  std::vector<std::vector<int>> leaving(segments.size()), arriving(segments.size());
  for (std::size_t s = 0; s < segments.size(); ++s) {
    if (!uniform(s)) continue;
    const ColorRegions& r = regions[s];
    const std::vector<int>& points = segments[s].points;
    for (std::size_t g = 0; g < r.members.size(); ++g) {
      if (static_cast<int>(g) == r.dominant || r.members[g].size() > params.max_stray_share * points.size()) continue;
      if (colorDifference(r.mean[g], r.mean[r.dominant]) <= max_color_difference) continue;
      std::map<int, int> links;  // adjacent segment -> links
      for (int j : r.members[g]) {
        for (int q : neighbours[points[j]]) {
          const int t = owner[q];
          if (t >= 0 && t != static_cast<int>(s)) ++links[t];
        }
      }
      int target = -1, most = 0;
      for (const auto& [t, n] : links) {
        if (n <= most || !uniform(t)) continue;
        if (colorDifference(r.mean[g], regions[t].mean[regions[t].dominant]) > max_color_difference) continue;
        most = n;
        target = t;
      }
      if (target < 0) continue;
      for (int j : r.members[g]) {
        leaving[s].push_back(points[j]);
        arriving[target].push_back(points[j]);
      }
    }
  }
  std::size_t moved = 0;
  for (std::size_t s = 0; s < segments.size(); ++s) {
    std::sort(leaving[s].begin(), leaving[s].end());
    std::sort(arriving[s].begin(), arriving[s].end());
    moved += arriving[s].size();
    std::vector<int> kept = difference(segments[s].points, leaving[s]);
    std::vector<int> merged;
    std::set_union(kept.begin(), kept.end(), arriving[s].begin(), arriving[s].end(), std::back_inserter(merged));
    segments[s].points = std::move(merged);
  }
  return moved;
}

void StrayColorStage::run(PipelineState& state) const {
  std::size_t moved = 0;
  if (state.has_color) moved = moveStrayColorPieces(state.segments, *state.cloud, state.evidence->neighbours(), params_);
  state.count("points_moved", moved);
}

}  // namespace symmetry_segmentation
