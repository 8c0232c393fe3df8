// Horizontal planes halfway up objects (see the header for why).
#include "symmetry_segmentation/symmetry/mid_height_hypotheses.h"

#include <algorithm>
#include <cmath>

#include <Eigen/Geometry>

#include "symmetry_segmentation/quantile.h"
#include "symmetry_segmentation/symmetry/symmetry_plane.h"

namespace symmetry_segmentation {
namespace {

constexpr float kDegToRad = static_cast<float>(M_PI) / 180.0f;

struct HorizontalFace {
  const SurfaceShape* surface = nullptr;
  float height = 0.0f;        ///< Median height over the table's plane.
  float table_height = 0.0f;  ///< The table top's height over its plane under the face's centroid.
  Eigen::AlignedBox2f extent;  ///< In the table plane's coordinates.
};

}  // namespace

std::vector<SymmetryHypothesis> midHeightHypotheses(const Cloud& cloud, const std::vector<SurfaceShape>& surfaces,
                                                    const TableTop& table, const UprightHypothesisParams& params,
                                                    float reach) {
  std::vector<SymmetryHypothesis> result;
  const float norm = table.plane.head<3>().norm();
  if (!(params.min_mid_height > 0.0f) || !(norm > 0.0f)) return result;
  const Eigen::Vector3f up = table.plane.head<3>() / norm;
  const float offset = table.plane[3] / norm;
  const Eigen::Vector3f e1 = up.unitOrthogonal();
  const Eigen::Vector3f e2 = up.cross(e1);
  const float horizontal_cos = std::cos(params.face_tilt_deg * kDegToRad);

  std::vector<HorizontalFace> faces;
  for (const SurfaceShape& surface : surfaces) {
    if (static_cast<int>(surface.points.size()) < params.min_surface_points) continue;
    if (!(surface.curvature < params.flat_curvature) || !(std::fabs(surface.face_normal.dot(up)) > horizontal_cos)) {
      continue;
    }
    HorizontalFace face;
    std::vector<float> heights;
    heights.reserve(surface.points.size());
    for (int i : surface.points) {
      const Eigen::Vector3f p = cloud.points[i].getVector3fMap();
      heights.push_back(up.dot(p) + offset);
      face.extent.extend(Eigen::Vector2f(e1.dot(p), e2.dot(p)));
    }
    face.height = quantileOf(heights, 0.5f);
    face.table_height = up.dot(surface.centroid) + offset - table.height(surface.centroid);
    face.surface = &surface;
    faces.push_back(std::move(face));
  }

  const auto horizontalPlane = [&](float height, const HorizontalFace& face) {
    SymmetryHypothesis h;
    h.plane.normal = up;
    h.plane.distance = offset - height;
    h.plane = canonicalPlane(h.plane);
    h.support = static_cast<int>(face.surface->points.size());
    h.anchor = face.surface->points;
    return h;
  };
  for (const HorizontalFace& face : faces) {
    if (face.height - face.table_height < params.min_mid_height) continue;
    result.push_back(horizontalPlane(0.5f * (face.height + face.table_height), face));
    Eigen::AlignedBox2f near = face.extent;
    near.min().array() -= reach;
    near.max().array() += reach;
    for (const HorizontalFace& lower : faces) {
      if (face.height - lower.height < params.min_mid_height || lower.height - lower.table_height < params.min_mid_height) {
        continue;
      }
      if (near.intersects(lower.extent)) result.push_back(horizontalPlane(0.5f * (face.height + lower.height), face));
    }
  }
  return result;
}

}  // namespace symmetry_segmentation
