#pragma once
// Stage 1: curves along the normal edges of the scene (where merged supervoxels meet), ordered,
// with a tangent per point. These are what symmetric pairs are matched on.

#include <vector>

#include <Eigen/Core>

#include "symmetry_segmentation/scene.h"
#include "symmetry_segmentation/symmetry/symmetry_params.h"

namespace symmetry_segmentation {

struct Curve {
  std::vector<int> points;                ///< Working-cloud indices, in order along the curve.
  std::vector<Eigen::Vector3f> tangents;  ///< Unit tangent per point (sign meaningless).
};

/// Merged-supervoxel label per working-cloud point (0 = unlabelled). Touching supervoxels merge
/// when their mean normals are within merge_normal_angle_deg, or when the normals where they
/// touch are and their mean normals are within 30 degrees (curved surfaces).
std::vector<int> mergedSegmentLabels(const Cloud& cloud, const SymmetryDetectionParams& params);

/// Points with a neighbour of another merged segment within params.boundary_radius.
std::vector<int> boundaryPoints(const Cloud& cloud, const std::vector<int>& labels,
                                const SymmetryDetectionParams& params);

/// Boundary points linked by a minimum spanning tree and split into disjoint ordered curves.
std::vector<Curve> linkCurves(const Cloud& cloud, const std::vector<int>& boundary,
                              const SymmetryDetectionParams& params);

/// As above, linking only points of one merged segment: the boundary band of an edge has a
/// row on either side, and each row becomes its own clean curve instead of a zigzag.
std::vector<Curve> linkCurves(const Cloud& cloud, const std::vector<int>& boundary, const std::vector<int>& labels,
                              const SymmetryDetectionParams& params);

/// Replaces the tangent of each curve point where two surfaces meet at an angle by their edge
/// direction (cross product of the two sides' mean normals near the point), which a coarse
/// voxel staircase does not disturb. Other points keep their along-curve tangent.
void useEdgeTangents(const Cloud& cloud, const std::vector<int>& labels, const SymmetryDetectionParams& params,
                     std::vector<Curve>& curves);

/// All of stage 1 on a working cloud with normals (linkCurves with labels, then useEdgeTangents).
std::vector<Curve> extractNormalEdgeCurves(const Cloud& cloud, const SymmetryDetectionParams& params);
/// As above, from merged-segment labels already computed (mergedSegmentLabels).
std::vector<Curve> extractNormalEdgeCurves(const Cloud& cloud, const std::vector<int>& labels,
                                           const SymmetryDetectionParams& params);

}  // namespace symmetry_segmentation
