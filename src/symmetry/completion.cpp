// Stage 20, completion: each segment's unseen side from its symmetry (see the header for why).
#include "symmetry_segmentation/symmetry/completion.h"

#include <cmath>
#include <limits>

#include "symmetry_segmentation/quantile.h"
#include "symmetry_segmentation/symmetry/pipeline_state.h"
#include "symmetry_segmentation/symmetry/reflection_data_term.h"
#include "symmetry_segmentation/symmetry/symmetry_plane.h"

namespace symmetry_segmentation {

std::vector<Eigen::Vector3f> hiddenSideReflections(const SceneEvidence& evidence, const std::vector<int>& points,
                                                   const SymmetryPlane& plane,
                                                   const std::optional<PlaneCoefficients>& table) {
  const Cloud& cloud = evidence.cloud();
  std::vector<Eigen::Vector3f> hidden;
  for (int index : points) {
    const Eigen::Vector3f position = cloud.points[index].getVector3fMap();
    if (!position.allFinite()) continue;
    if (evidence.reflection(index, plane).landing != ReflectionLanding::Occluded) continue;
    const Eigen::Vector3f reflected = reflectPoint(plane, position);
    // The data term forgives reflections just under the table (plane errors at the base); the
    // table hides nothing of an object standing on it.
    if (table && table->head<3>().dot(reflected) + (*table)[3] < 0.0f) continue;
    hidden.push_back(reflected);
  }
  return hidden;
}

ObjectBox completedBox(const std::vector<Eigen::Vector3f>& visible, const std::vector<Eigen::Vector3f>& added,
                       const std::optional<Eigen::Vector3f>& up, float trim) {
  Cloud seen_cloud;
  seen_cloud.reserve(visible.size());
  for (const Eigen::Vector3f& p : visible) {
    PointT point;
    point.getVector3fMap() = p;
    seen_cloud.push_back(point);
  }
  // Turned as the visible points are: their footprint is measured, the added one inferred through
  // a plane that may be a few degrees off (turning the box with it was worse on single views).
  std::vector<int> seen(visible.size());
  for (std::size_t i = 0; i < seen.size(); ++i) seen[i] = static_cast<int>(i);
  ObjectBox box = objectBox(seen_cloud, seen, up);
  if (visible.empty() || added.empty()) return box;
  Eigen::Vector3f low = Eigen::Vector3f::Constant(std::numeric_limits<float>::max());
  Eigen::Vector3f high = -low;
  for (const Eigen::Vector3f& p : visible) {
    low = low.cwiseMin(box.axes.transpose() * p);
    high = high.cwiseMax(box.axes.transpose() * p);
  }
  for (int k = 0; k < 3; ++k) {
    std::vector<float> along;
    along.reserve(added.size());
    for (const Eigen::Vector3f& p : added) along.push_back(box.axes.col(k).dot(p));
    const auto [added_low, added_high] = trimmedRange(along, trim);
    low[k] = std::min(low[k], added_low);
    high[k] = std::max(high[k], added_high);
  }
  box.center = box.axes * (0.5f * (low + high));
  box.size = high - low;
  return box;
}

Eigen::Isometry3f symmetryFrame(const Eigen::Vector3f& centroid, const SymmetryPlane& plane,
                                const std::optional<Eigen::Vector3f>& up) {
  const Eigen::Vector3f x = plane.normal.normalized();
  Eigen::Vector3f z = x.unitOrthogonal();
  if (up) {
    const Eigen::Vector3f vertical = *up - up->dot(x) * x;
    if (vertical.norm() > 1e-3f * up->norm()) z = vertical.normalized();
  }
  Eigen::Matrix3f axes;
  axes.col(0) = x;
  axes.col(1) = z.cross(x);
  axes.col(2) = z;
  Eigen::Isometry3f frame = Eigen::Isometry3f::Identity();
  frame.linear() = axes;
  frame.translation() = centroid - (x.dot(centroid) + plane.distance) * x;
  return frame;
}

void CompletionStage::run(PipelineState& state) const {
  std::optional<PlaneCoefficients> table;
  if (state.prepared.has_table) table = state.prepared.table_plane;
  std::size_t added = 0;
  for (CandidateSegment& segment : state.segments) {
    segment.completion = hiddenSideReflections(*state.evidence, segment.points, segment.plane, table);
    added += segment.completion->size();
  }
  state.count("points", added);
}

}  // namespace symmetry_segmentation
