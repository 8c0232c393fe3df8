#pragma once
// A curve's positions and tangents copied out of the cloud once, for the O(m^2) matching loops.

#include <vector>

#include <Eigen/Core>

#include "symmetry_segmentation/symmetry/symmetry_hypotheses.h"

namespace symmetry_segmentation {

struct CurveGeometry {
  std::vector<Eigen::Vector3f> positions;
  std::vector<Eigen::Vector3f> tangents;
  Eigen::Vector3f min = Eigen::Vector3f::Zero();  ///< Bounding box.
  Eigen::Vector3f max = Eigen::Vector3f::Zero();

  CurveGeometry(const Cloud& cloud, const Curve& curve) : tangents(curve.tangents) {
    positions.reserve(curve.points.size());
    for (int index : curve.points) positions.push_back(cloud.points[index].getVector3fMap());
    if (!positions.empty()) min = max = positions.front();
    for (const auto& p : positions) {
      min = min.cwiseMin(p);
      max = max.cwiseMax(p);
    }
  }

  /// Smallest distance between the two bounding boxes.
  float boxDistance(const CurveGeometry& other) const {
    const Eigen::Vector3f gap = (other.min - max).cwiseMax(min - other.max).cwiseMax(0.0f);
    return gap.norm();
  }
};

/// matchCurvePair on prepared geometry; `same` = the two are one curve.
std::vector<PlaneSample> matchCurveGeometry(const CurveGeometry& a, const CurveGeometry& b, bool same,
                                            const CurvePairParams& params);

}  // namespace symmetry_segmentation
