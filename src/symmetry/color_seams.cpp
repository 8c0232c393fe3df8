// Stage 15, color_seams: segments of flush objects split at their colour seams (see the header for why).
#include "symmetry_segmentation/symmetry/color_seams.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <utility>

#include <Eigen/Core>
#include <Eigen/Eigenvalues>

#include "color_lab.h"
#include "symmetry_segmentation/symmetry/color_histogram.h"
#include "disjoint_sets.h"
#include "symmetry_segmentation/quantile.h"
#include "symmetry_segmentation/symmetry/object_size.h"
#include "symmetry_segmentation/symmetry/pipeline_state.h"
#include "symmetry_segmentation/symmetry/smoothness_weight.h"
#include "symmetry_segmentation/symmetry/sorted_indices.h"

namespace symmetry_segmentation {
namespace {

// A seam whose second axis is at least this share of its first (in extent) has a plane of its own.
constexpr float kPlanarSeamRatio = 0.25f;
// A part's far end from its seam: a high quantile, not the farthest point (a speck of noise).
constexpr float kFarEndQuantile = 0.98f;

// The colour parts of a segment: per position its part, numbered from 0, the uniform parts
// first. Empty unless there are two or more and together they cover most of the segment.
struct ColorParts {
  std::vector<int> part;
  int count = 0;
  int uniform_count = 0;  // parts 0..uniform_count-1 are uniform colour regions, the rest print
};

// The large uniform-colour regions, and where those leave much of the segment uncovered, the
// large connected stretches of what is left: print, which is no uniform region at any
// threshold (a printed box next to a plain one is one large region and a hundred small ones).
// Each part is then grown over the segment's links into the small regions around it (blended
// colours at the seam, print within a plain part).
ColorParts colorParts(const std::vector<int>& points, const std::vector<Eigen::Vector3f>& lab,
                      const std::vector<std::vector<int>>& neighbours, const ColorSeamParams& params) {
  DisjointSets regions = colorRegions(points, lab, neighbours, params.max_color_difference);
  std::map<int, int> sizes;
  for (std::size_t j = 0; j < points.size(); ++j) ++sizes[regions.find(static_cast<int>(j))];
  const double min_size = std::max<double>(params.min_part_points, params.min_part_fraction * points.size());
  const double min_covered = params.min_coverage * points.size();
  ColorParts parts;
  std::map<int, int> part_of_root;
  std::size_t covered = 0;
  for (const auto& [root, size] : sizes) {
    if (size < min_size) continue;
    part_of_root.emplace(root, parts.count++);
    covered += size;
  }
  parts.uniform_count = parts.count;
  std::vector<int> part(points.size(), -1);
  for (std::size_t j = 0; j < points.size(); ++j) {
    const auto it = part_of_root.find(regions.find(static_cast<int>(j)));
    if (it != part_of_root.end()) part[j] = it->second;
  }
  if (covered < min_covered) {
    DisjointSets rest(points.size());
    forEachLink(points, neighbours, [&](int j, int k) {
      if (part[j] < 0 && part[k] < 0) rest.unite(j, k);
    });
    std::map<int, int> rest_sizes;
    for (std::size_t j = 0; j < points.size(); ++j) {
      if (part[j] < 0) ++rest_sizes[rest.find(static_cast<int>(j))];
    }
    std::map<int, int> part_of_rest;
    for (const auto& [root, size] : rest_sizes) {
      if (size < min_size) continue;
      part_of_rest.emplace(root, parts.count++);
      covered += size;
    }
    for (std::size_t j = 0; j < points.size(); ++j) {
      const auto it = part[j] < 0 ? part_of_rest.find(rest.find(static_cast<int>(j))) : part_of_rest.end();
      if (it != part_of_rest.end()) part[j] = it->second;
    }
  }
  if (parts.count < 2 || covered < min_covered) return {};

  std::vector<int> frontier;
  for (std::size_t j = 0; j < points.size(); ++j) {
    if (part[j] >= 0) frontier.push_back(static_cast<int>(j));
  }
  std::vector<int> part_sizes(parts.count, 0);
  for (int j : frontier) ++part_sizes[part[j]];
  // Breadth first, so each small region goes to the large regions nearest over the surface.
  for (std::size_t head = 0; head < frontier.size(); ++head) {
    const int j = frontier[head];
    const int p = points[j];
    if (p < 0 || static_cast<std::size_t>(p) >= neighbours.size()) continue;
    for (int q : neighbours[p]) {
      const int k = positionIn(points, q);
      if (k < 0 || part[k] >= 0) continue;
      part[k] = part[j];
      frontier.push_back(k);
    }
  }
  // Points no link reaches (a detached speck) join the largest part.
  const int largest = static_cast<int>(std::max_element(part_sizes.begin(), part_sizes.end()) - part_sizes.begin());
  for (int& p : part) {
    if (p < 0) p = largest;
  }
  parts.part = std::move(part);
  return parts;
}

// Where a seam lies: the mean of its links' ends and their principal axes (eigenvalues
// ascending: the last two axes span the seam's plane, the first is its normal).
struct SeamShape {
  Eigen::Vector3f mean;
  Eigen::Matrix3f axes;
  Eigen::Vector3f spread;
};

SeamShape seamShape(const std::vector<int>& ends, const std::vector<int>& points, const Cloud& cloud) {
  SeamShape shape;
  shape.mean = Eigen::Vector3f::Zero();
  for (int j : ends) shape.mean += cloud[points[j]].getVector3fMap();
  shape.mean /= static_cast<float>(ends.size());
  Eigen::Matrix3f scatter = Eigen::Matrix3f::Zero();
  for (int j : ends) {
    const Eigen::Vector3f d = cloud[points[j]].getVector3fMap() - shape.mean;
    scatter += d * d.transpose();
  }
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3f> solver(scatter);
  shape.axes = solver.eigenvectors();
  shape.spread = solver.eigenvalues();
  return shape;
}

// How far the middles of a seam's links lie from the plane through them (RMS, m). Two objects
// meet flush on one plane, their contact (boxes in a row, a box on a box of its footprint); a
// print's colour edge steps and wanders across an object's faces.
float seamOffPlane(const std::vector<int>& ends, const std::vector<int>& points, const Cloud& cloud) {
  std::vector<Eigen::Vector3f> middles;
  middles.reserve(ends.size() / 2);
  Eigen::Vector3f mean = Eigen::Vector3f::Zero();
  for (std::size_t e = 0; e + 1 < ends.size(); e += 2) {
    middles.push_back(0.5f * (cloud[points[ends[e]]].getVector3fMap() + cloud[points[ends[e + 1]]].getVector3fMap()));
    mean += middles.back();
  }
  if (middles.empty()) return 0.0f;
  mean /= static_cast<float>(middles.size());
  Eigen::Matrix3f scatter = Eigen::Matrix3f::Zero();
  for (const Eigen::Vector3f& m : middles) scatter += (m - mean) * (m - mean).transpose();
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3f> solver(scatter / static_cast<float>(middles.size()));
  return std::sqrt(std::max(0.0f, solver.eigenvalues()(0)));
}

// Whether a seam runs right across both parts it divides (their positions in `points`: `of_a`,
// `of_b`): in some direction within the seam's plane it spans most of each part's extent. Where
// a box stands on a box of its footprint the seam is the whole footprint's outline; between
// boxes of one depth in a row it runs from the front to the back; the colour edge round a
// bottle's cap is a ring much narrower than the bottle.
bool seamSpansBoth(const std::vector<int>& ends, const SeamShape& shape, const std::vector<int>& of_a,
                   const std::vector<int>& of_b, const std::vector<int>& points, const Cloud& cloud, float min_span) {
  const Eigen::Vector3f first = shape.axes.col(2);
  const Eigen::Vector3f second = shape.axes.col(1);
  auto extent = [&](const std::vector<int>& positions, const Eigen::Vector3f& direction) {
    float low = std::numeric_limits<float>::max(), high = std::numeric_limits<float>::lowest();
    for (int j : positions) {
      const float t = direction.dot(cloud[points[j]].getVector3fMap());
      low = std::min(low, t);
      high = std::max(high, t);
    }
    return high > low ? high - low : 0.0f;
  };
  constexpr int kDirections = 12;  // Fixed: every 15 degrees, finer than any span test needs.
  for (int step = 0; step < kDirections; ++step) {
    const float angle = static_cast<float>(M_PI) * step / kDirections;
    const Eigen::Vector3f direction = std::cos(angle) * first + std::sin(angle) * second;
    const float seam = extent(ends, direction);
    if (seam >= min_span * extent(of_a, direction) && seam >= min_span * extent(of_b, direction)) return true;
  }
  return false;
}

// Whether most of `piece`'s matched reflections about `plane` land on `target` (sorted).
bool mirroredOnto(const std::vector<int>& piece, const std::vector<int>& target, const SymmetryPlane& plane,
                  const SceneEvidence& evidence, const ColorSeamParams& params) {
  int matched = 0;
  int onto_target = 0;
  for (int p : piece) {
    const int q = evidence.match(p, plane);
    if (q < 0) continue;
    ++matched;
    onto_target += contains(target, q) ? 1 : 0;
  }
  return matched >= params.min_seam_links && onto_target >= params.min_self_mirrored_fraction * matched;
}

bool mirroredOntoItself(const std::vector<int>& piece, const SymmetryPlane& plane, const SceneEvidence& evidence,
                        const ColorSeamParams& params) {
  return mirroredOnto(piece, piece, plane, evidence, params);
}

// The plane parallel to a seam halfway between the seam and the far end of part `a` (its own
// points' positions `of_a`): where a box's middle is when the seam is one of its faces (boxes
// in a row, a box on a box). Across the seam: the normal of the seam's plane, or for a seam seen
// as one line, the way from `b` to `a` square to that line.
SymmetryPlane seamMidPlane(const SeamShape& seam, const std::vector<int>& of_a, const std::vector<int>& of_b,
                           const std::vector<int>& points, const Cloud& cloud) {
  const auto mean_of = [&](const std::vector<int>& positions) {
    Eigen::Vector3f mean = Eigen::Vector3f::Zero();
    for (int j : positions) mean += cloud[points[j]].getVector3fMap();
    return Eigen::Vector3f(mean / static_cast<float>(positions.size()));
  };
  const Eigen::Vector3f along = seam.axes.col(2);
  Eigen::Vector3f across = mean_of(of_a) - mean_of(of_b);
  // A seam of two strokes (over a box's top and down its front) has a plane of its own.
  if (seam.spread(1) > kPlanarSeamRatio * kPlanarSeamRatio * seam.spread(2)) {
    across = seam.axes.col(0) * (seam.axes.col(0).dot(across) < 0.0f ? -1.0f : 1.0f);
  } else {
    across -= across.dot(along) * along;
  }
  SymmetryPlane plane;
  plane.normal = across.normalized();
  std::vector<float> heights;
  heights.reserve(of_a.size());
  for (int j : of_a) heights.push_back(plane.normal.dot(cloud[points[j]].getVector3fMap()));
  const float far = quantileOf(heights, kFarEndQuantile);
  plane.distance = -0.5f * (plane.normal.dot(seam.mean) + far);
  return plane;
}

// Whether a colour part is an object of its own: a plane mirrors most of its matched reflections
// onto itself (boxes in a row or in a stack share such a plane and each mirrors onto itself; a
// print patch or a handle's colour mirrors onto the rest of its object or nowhere), and it is
// more than one flat face (any plane across a face mirrors it onto itself, and a box's face in
// another print is no object).
bool standsAlone(const std::vector<int>& piece, const std::vector<SymmetryPlane>& planes,
                 const std::vector<CandidateSegment>& found, const SceneEvidence& evidence,
                 const ColorSeamParams& params) {
  // The segment's plane (or others given), or that of a found segment covering a good share of
  // the piece (a stack of two boxes may come with the horizontal plane that mirrors one box onto
  // the other).
  bool mirrored = std::any_of(planes.begin(), planes.end(), [&](const SymmetryPlane& plane) {
    return mirroredOntoItself(piece, plane, evidence, params);
  });
  for (std::size_t i = 0; i < found.size() && !mirrored; ++i) {
    if (found[i].points.empty() || intersectionSize(found[i].points, piece) < params.min_plane_share * piece.size()) {
      continue;
    }
    mirrored = mirroredOntoItself(piece, found[i].plane, evidence, params);
  }
  if (!mirrored) return false;
  const Cloud::ConstPtr cloud(&evidence.cloud(), [](const Cloud*) {});  // not owned: PCL wants a shared pointer
  return largestPlanePoints(cloud, piece, params.on_plane_distance).size() <= params.max_piece_plane_share * piece.size();
}

// Groups the parts into objects and renumbers `part` to 0..count-1; returns the count. Two
// parts are different objects where their seam has a good share of concave links (where objects
// touch: a bowl on a box, a short box's top against its taller neighbour's side) and the
// smaller is no mere handle, or where it is mostly flat rather than convex (a convex seam is one
// object's own edge: a can's rim round its lid) and runs right across both - between uniform
// parts only: print meeting a plain panel flush is the look of most printed packaging, and says
// nothing of where an object ends. Other seams join one object's differently coloured parts; a
// part with no seam to any other (the pieces of one box seen either side of a board) joins the
// part closest to it in colour.
int objectsAtColorSeams(const std::vector<int>& points, const std::vector<Eigen::Vector3f>& lab, const Cloud& cloud,
                       const std::vector<std::vector<int>>& neighbours, const SymmetryPlane& plane,
                       const std::vector<CandidateSegment>& found, const SceneEvidence& evidence,
                       const ColorSeamParams& params, std::vector<int>& part, int count, int uniform_count) {
  const float min_flat_cos = std::cos(params.flat_link_angle_deg * static_cast<float>(M_PI) / 180.0f);
  struct Seam {
    int links = 0;
    int flat_links = 0;
    int convex_links = 0;
    std::vector<int> ends;  // segment positions at either end of its links
  };
  std::map<std::pair<int, int>, Seam> seams;  // keyed by (part a < part b)
  forEachLink(points, neighbours, [&](int j, int k) {
    if (part[j] == part[k]) return;
    Seam& seam = seams[std::minmax(part[j], part[k])];
    ++seam.links;
    const auto& p = cloud[points[j]];
    const auto& q = cloud[points[k]];
    if (p.getNormalVector3fMap().dot(q.getNormalVector3fMap()) > min_flat_cos) {
      ++seam.flat_links;
    } else if (isConvexLink(p.getVector3fMap(), p.getNormalVector3fMap(), q.getVector3fMap(),
                            q.getNormalVector3fMap())) {
      ++seam.convex_links;
    }
    seam.ends.push_back(j);
    seam.ends.push_back(k);
  });
  std::vector<std::vector<int>> pieces(count);  // sorted, as `points` is
  for (std::size_t j = 0; j < points.size(); ++j) pieces[part[j]].push_back(points[j]);
  std::vector<int> alone(count, -1);  // standsAlone per part, computed when first asked
  const auto stands_alone = [&](int a) {
    if (alone[a] < 0) alone[a] = standsAlone(pieces[a], {plane}, found, evidence, params) ? 1 : 0;
    return alone[a] == 1;
  };
  std::vector<std::vector<int>> positions(count);  // per part, its positions in `points`
  for (std::size_t j = 0; j < points.size(); ++j) positions[part[j]].push_back(static_cast<int>(j));
  // A box at the end of a flush row mirrors onto itself about its own middle, where the
  // segment's plane (the middle box's) mirrors it elsewhere. Not where that plane mirrors it onto
  // the part across the seam: one object printed in two colours either side of its plane.
  const auto stands_alone_at = [&](const SeamShape& seam, int a, int b) {
    if (stands_alone(a)) return true;
    if (mirroredOnto(pieces[a], pieces[b], plane, evidence, params)) return false;
    return standsAlone(pieces[a], {seamMidPlane(seam, positions[a], positions[b], points, cloud)}, found, evidence,
                       params);
  };
  // A flat seam parts two objects where it lies on one plane, runs right across both and each
  // stands alone.
  const auto flush_objects = [&](const Seam& seam, int a, int b) {
    if (params.max_flush_seam_offset > 0.0f && seamOffPlane(seam.ends, points, cloud) > params.max_flush_seam_offset) {
      return false;
    }
    const SeamShape shape = seamShape(seam.ends, points, cloud);
    return seamSpansBoth(seam.ends, shape, positions[a], positions[b], points, cloud, params.min_seam_span) &&
           stands_alone_at(shape, a, b) && stands_alone_at(shape, b, a);
  };
  const auto large_or_alone = [&](int a) {
    return pieces[a].size() >= params.min_touching_part_fraction * points.size() || stands_alone(a);
  };
  DisjointSets objects(count);
  std::vector<std::pair<int, int>> between_objects;
  for (const auto& [pair, seam] : seams) {
    if (seam.links < params.min_seam_links) continue;
    const int concave_links = seam.links - seam.flat_links - seam.convex_links;
    const bool touching = concave_links >= params.min_seam_links &&
                          concave_links >= params.min_concave_seam_fraction * seam.links &&
                          large_or_alone(pair.first) && large_or_alone(pair.second);
    const bool uniform = pair.first < uniform_count && pair.second < uniform_count;
    const bool flat = params.split_flush_seams && uniform && seam.flat_links >= params.min_seam_links &&
                      seam.flat_links >= params.min_flat_seam_fraction * (seam.flat_links + seam.convex_links);
    // Parts sharing one print's palette are one object's, whatever their seam (a printed U's
    // plain face meets its print at the U's inner creases).
    const auto one_print = [&]() {
      return params.min_color_overlap > 0.0f &&
             colorOverlap(cloud, pieces[pair.first], pieces[pair.second]) >= params.min_color_overlap;
    };
    if ((touching || (flat && flush_objects(seam, pair.first, pair.second))) && !one_print()) {
      between_objects.push_back(pair);
    } else {
      objects.unite(pair.first, pair.second);
    }
  }
  std::vector<char> apart(count, 0);
  for (const auto& [a, b] : between_objects) {
    if (objects.find(a) == objects.find(b)) continue;
    apart[objects.find(a)] = 1;
    apart[objects.find(b)] = 1;
  }
  std::vector<Eigen::Vector3f> color_sum(count, Eigen::Vector3f::Zero());
  std::vector<int> size(count, 0);
  for (std::size_t j = 0; j < points.size(); ++j) {
    color_sum[objects.find(part[j])] += lab[j];
    ++size[objects.find(part[j])];
  }
  for (int g = 0; g < count; ++g) {
    if (objects.find(g) != g || apart[g]) continue;
    int closest = -1;
    float least = std::numeric_limits<float>::max();
    for (int h = 0; h < count; ++h) {
      if (h == g || objects.find(h) != h) continue;
      const float difference = colorDifference(color_sum[g] / size[g], color_sum[h] / size[h]);
      if (difference < least) {
        least = difference;
        closest = h;
      }
    }
    if (closest >= 0) objects.unite(g, closest);
  }
  std::map<int, int> renumbered;
  for (int& p : part) p = renumbered.emplace(objects.find(p), static_cast<int>(renumbered.size())).first->second;
  return static_cast<int>(renumbered.size());
}

// How much `points` contradicts `plane`: reflections into free space (as the occlusion score
// grades them) plus reflections onto points outside it.
float contradiction(const std::vector<int>& points, const SymmetryPlane& plane, const SceneEvidence& evidence) {
  int foreign = 0;
  for (int p : points) {
    const int q = evidence.match(p, plane);
    if (q >= 0 && !contains(points, q)) ++foreign;
  }
  return (1.0f - evidence.scores(points, plane).occlusion) + static_cast<float>(foreign) / points.size();
}

CandidateSegment withBestPlane(std::vector<int> points, const SymmetryPlane& own_plane,
                               const std::vector<CandidateSegment>& found, const SceneEvidence& evidence,
                               const ColorSeamParams& params) {
  SymmetryPlane best = own_plane;
  float least = contradiction(points, own_plane, evidence);
  for (const CandidateSegment& other : found) {
    if (other.points.empty() || intersectionSize(other.points, points) < params.min_plane_share * points.size()) continue;
    const float value = contradiction(points, other.plane, evidence);
    if (value < least) {
      least = value;
      best = other.plane;
    }
  }
  CandidateSegment segment;
  segment.plane = best;
  segment.scores = evidence.scores(points, best);
  segment.points = std::move(points);
  return segment;
}

}  // namespace

std::size_t splitAtColorSeams(std::vector<CandidateSegment>& segments, const std::vector<CandidateSegment>& found,
                              const SceneEvidence& evidence, const ColorSeamParams& params) {
  const Cloud& cloud = evidence.cloud();
  const std::vector<std::vector<int>>& neighbours = evidence.neighbours();
  std::size_t split = 0;
  const std::size_t original = segments.size();
  for (std::size_t i = 0; i < original; ++i) {
    const std::vector<int>& points = segments[i].points;
    std::vector<Eigen::Vector3f> lab(points.size());
    for (std::size_t j = 0; j < points.size(); ++j) lab[j] = toLab(cloud[points[j]]);
    ColorParts parts = colorParts(points, lab, neighbours, params);
    if (parts.part.empty()) continue;
    std::vector<int>& part = parts.part;
    const int count = objectsAtColorSeams(points, lab, cloud, neighbours, segments[i].plane, found, evidence, params,
                                          part, parts.count, parts.uniform_count);
    if (count < 2) continue;
    std::vector<std::vector<int>> pieces(count);
    for (std::size_t j = 0; j < points.size(); ++j) pieces[part[j]].push_back(points[j]);
    // The seam is where the objects end, not a cut through one surface: its smooth links do not
    // count against either part's smoothness score.
    std::vector<int> seam_links(count, 0);
    const float min_smooth_cos = std::cos(params.flat_link_angle_deg * static_cast<float>(M_PI) / 180.0f);
    forEachLink(points, neighbours, [&](int j, int k) {
      if (part[j] == part[k] ||
          cloud[points[j]].getNormalVector3fMap().dot(cloud[points[k]].getNormalVector3fMap()) <= min_smooth_cos) {
        return;
      }
      ++seam_links[part[j]];
      ++seam_links[part[k]];
    });
    ++split;
    const SymmetryPlane plane = segments[i].plane;
    for (std::size_t p = 0; p < pieces.size(); ++p) {
      CandidateSegment piece = withBestPlane(std::move(pieces[p]), plane, found, evidence, params);
      piece.scores.smoothness = std::max(0.0f, piece.scores.smoothness - static_cast<float>(seam_links[p]) / piece.points.size());
      if (p == 0) segments[i] = std::move(piece);
      else segments.push_back(std::move(piece));
    }
  }
  return split;
}

void ColorSeamStage::run(PipelineState& state) const {
  std::size_t split = 0;
  if (state.has_color) {
    ColorSeamParams params = params_;
    params.min_part_points = filter_.min_segment_points;
    params.flat_link_angle_deg = filter_.smooth_normal_angle_deg;
    params.on_plane_distance = onPlaneDistance(voxel_size_);
    params.min_color_overlap = min_color_overlap_;
    split = splitAtColorSeams(state.segments, state.candidates, *state.evidence, params);
  }
  state.count("split", split);
}

}  // namespace symmetry_segmentation
