#pragma once
// Part of stage 16, coaxial_pieces (our addition): a mug's handle or a jug's spout. The body is a
// surface of revolution, so every vertical plane through its axis is a symmetry of it, and the
// plane the cut happened to take (an upright plane from one side of the body) sends the handle's
// reflection into free space: the cut leaves the handle out. Only one plane through the axis
// also mirrors the handle onto itself - the one through the handle. So a piece of the body's
// island beside it, small against it, within its heights, that the vertical plane through the
// axis and the piece's middle mirrors onto itself, is joined to it on that plane.
#include <vector>

#include <Eigen/Core>

#include "symmetry_segmentation/symmetry/scene_evidence.h"
#include "symmetry_segmentation/symmetry/segment_filter.h"

namespace symmetry_segmentation {

/// For `body` (turning about the vertical axis through `axis_point`, `up` the table's unit
/// normal): each connected piece (over the evidence's links) of `island` outside the body that
/// touches it, has at least 10 points and at most `max_share` of the body's, lies within the
/// body's heights, and of whose points at least half are mirrored onto the piece by the vertical
/// plane through the axis and the piece's middle - the body with that piece, on that plane,
/// scored. `island` and `body.points` sorted.
std::vector<CandidateSegment> bodiesWithHandles(const CandidateSegment& body, const Eigen::Vector3f& axis_point,
                                                const std::vector<int>& island, const SceneEvidence& evidence,
                                                const Eigen::Vector3f& up, float max_share);

}  // namespace symmetry_segmentation
