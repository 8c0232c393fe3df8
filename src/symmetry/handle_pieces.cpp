// A surface of revolution's handle joined to it (see the header for why).
#include "symmetry_segmentation/symmetry/handle_pieces.h"

#include <algorithm>
#include <iterator>

#include "segment_links.h"
#include "symmetry_segmentation/symmetry/coaxial_pieces.h"
#include "symmetry_segmentation/symmetry/sorted_indices.h"
#include "symmetry_segmentation/symmetry/symmetry_plane.h"

namespace symmetry_segmentation {
namespace {

// Fewer points than this (1 cm voxels) are no handle to speak of.
constexpr std::size_t kMinHandlePoints = 10;
// Of a handle's points, this share at least lands on the handle under its plane.
constexpr float kMinSelfMirrored = 0.5f;
// A piece whose middle is this close to the axis (horizontally) gives no plane.
constexpr float kMinOffAxis = 1e-3f;

// Connected pieces of `points` (sorted) over `neighbours`, as sorted index lists.
std::vector<std::vector<int>> linkedPieces(const std::vector<int>& points, const std::vector<std::vector<int>>& neighbours) {
  int count = 0;
  const std::vector<int> piece = linkedPieceOf(points, neighbours, count);
  std::vector<std::vector<int>> pieces(count);
  for (std::size_t j = 0; j < points.size(); ++j) pieces[piece[j]].push_back(points[j]);  // in order: sorted
  return pieces;
}

bool touches(const std::vector<int>& piece, const std::vector<int>& body, const std::vector<std::vector<int>>& neighbours) {
  for (int p : piece) {
    if (p < 0 || static_cast<std::size_t>(p) >= neighbours.size()) continue;
    for (int q : neighbours[p]) {
      if (contains(body, q)) return true;
    }
  }
  return false;
}

}  // namespace

std::vector<CandidateSegment> bodiesWithHandles(const CandidateSegment& body, const Eigen::Vector3f& axis_point,
                                                const std::vector<int>& island, const SceneEvidence& evidence,
                                                const Eigen::Vector3f& up, float max_share) {
  std::vector<CandidateSegment> result;
  if (!(max_share > 0.0f) || body.points.empty()) return result;
  const Cloud& cloud = evidence.cloud();
  const std::vector<std::vector<int>>& neighbours = evidence.neighbours();
  std::vector<int> outside;
  std::set_difference(island.begin(), island.end(), body.points.begin(), body.points.end(), std::back_inserter(outside));
  const std::pair<float, float> body_heights = heightRange(cloud, body.points, up);
  for (const std::vector<int>& piece : linkedPieces(outside, neighbours)) {
    if (piece.size() < kMinHandlePoints || static_cast<float>(piece.size()) > max_share * body.points.size()) continue;
    if (!touches(piece, body.points, neighbours)) continue;
    // A handle lies within the body's heights; what stands on it or under it does not.
    const std::pair<float, float> heights = heightRange(cloud, piece, up);
    if (heights.first < body_heights.first || heights.second > body_heights.second) continue;
    Eigen::Vector3f middle = Eigen::Vector3f::Zero();
    for (int p : piece) middle += cloud[p].getVector3fMap();
    middle /= static_cast<float>(piece.size());
    Eigen::Vector3f off_axis = middle - axis_point;
    off_axis -= off_axis.dot(up) * up;
    if (!(off_axis.norm() > kMinOffAxis)) continue;
    SymmetryPlane plane;
    plane.normal = up.cross(off_axis).normalized();
    plane.distance = -plane.normal.dot(axis_point);
    plane = canonicalPlane(plane);
    std::size_t onto_itself = 0;
    for (int p : piece) onto_itself += contains(piece, evidence.match(p, plane)) ? 1 : 0;
    if (static_cast<float>(onto_itself) < kMinSelfMirrored * static_cast<float>(piece.size())) continue;
    CandidateSegment joint;
    std::set_union(body.points.begin(), body.points.end(), piece.begin(), piece.end(), std::back_inserter(joint.points));
    joint.plane = plane;
    joint.scores = evidence.scores(joint.points, plane);
    result.push_back(std::move(joint));
  }
  return result;
}

}  // namespace symmetry_segmentation
