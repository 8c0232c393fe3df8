#pragma once
// A SceneEvidence whose answers a test sets: a cloud and its links, and a function for each
// question (where a reflection lands, scores, free space, creases), so a stage's unit test can
// pose exactly the situation it is about.

#include <functional>
#include <memory>
#include <utility>
#include <vector>

#include "symmetry_segmentation/symmetry/scene_evidence.h"

namespace test_support {

namespace ss = symmetry_segmentation;

class FakeEvidence : public ss::SceneEvidence {
 public:
  explicit FakeEvidence(ss::Cloud cloud, std::vector<std::vector<int>> neighbours = {})
      : cloud_(std::move(cloud)), neighbours_(std::move(neighbours)) {
    neighbours_.resize(cloud_.size());
  }
  /// A cloud of `points` points at the origin.
  explicit FakeEvidence(std::size_t points, std::vector<std::vector<int>> neighbours = {})
      : FakeEvidence(ss::Cloud(static_cast<uint32_t>(points), 1), std::move(neighbours)) {}

  /// The point a reflection lands on (-1: unobserved space, no evidence). Default: none.
  std::function<int(int index, const ss::SymmetryPlane& plane)> lands_on = [](int, const ss::SymmetryPlane&) {
    return -1;
  };
  /// Default: occlusion 1, smoothness 0.
  std::function<ss::SegmentScores(const std::vector<int>&, const ss::SymmetryPlane&)> score =
      [](const std::vector<int>&, const ss::SymmetryPlane&) { return ss::SegmentScores{1.0f, 0.0f}; };
  /// Default: nowhere.
  std::function<bool(const Eigen::Vector3f&)> free = [](const Eigen::Vector3f&) { return false; };
  /// Where a reflection that lands on no point is in observed free space (reflection(): landing
  /// Free, foreground cost 1). Default: unset, such reflections are occluded.
  std::function<bool(const Eigen::Vector3f&)> free_landing;
  /// Default: from the cloud's normals (SceneEvidence).
  std::function<bool(int a, int b)> crease;
  /// Creases that depend on the angle asked for (first when set).
  std::function<bool(int a, int b, float angle_deg)> crease_at_angle;

  const ss::Cloud& cloud() const override { return cloud_; }
  const std::vector<std::vector<int>>& neighbours() const override { return neighbours_; }
  ss::ReflectionEvidence reflection(int index, const ss::SymmetryPlane& plane) const override {
    ss::ReflectionEvidence evidence;
    evidence.match = lands_on(index, plane);
    evidence.landing = evidence.match >= 0 ? ss::ReflectionLanding::OnPoint : ss::ReflectionLanding::Occluded;
    evidence.foreground_strength = evidence.match >= 0 ? 1.0f : 0.0f;
    evidence.cost_background = evidence.foreground_strength;
    if (evidence.match < 0 && free_landing) {
      const Eigen::Vector3f p = cloud_[index].getVector3fMap();
      if (free_landing(p - 2.0f * (plane.normal.dot(p) + plane.distance) * plane.normal)) {
        evidence.landing = ss::ReflectionLanding::Free;
        evidence.cost_foreground = 1.0f;
      }
    }
    return evidence;
  }
  ss::SegmentScores scores(const std::vector<int>& points, const ss::SymmetryPlane& plane) const override {
    return score(points, plane);
  }
  bool observedFree(const Eigen::Vector3f& point) const override { return free(point); }
  bool concaveCrease(int a, int b, float angle_deg) const override {
    if (crease_at_angle) return crease_at_angle(a, b, angle_deg);
    return crease ? crease(a, b) : ss::SceneEvidence::concaveCrease(a, b, angle_deg);
  }

  /// Reflections land on the cloud point nearest the mirror image within `radius`, if any.
  void landOnNearestWithin(float radius) {
    // Its own copy of the points: the evidence may be copied, and `this` with it.
    auto points = std::make_shared<std::vector<Eigen::Vector3f>>();
    for (const auto& p : cloud_.points) points->push_back(p.getVector3fMap());
    lands_on = [points, radius](int index, const ss::SymmetryPlane& plane) {
      const Eigen::Vector3f& p = (*points)[index];
      const Eigen::Vector3f image = p - 2.0f * (plane.normal.dot(p) + plane.distance) * plane.normal;
      int best = -1;
      float nearest = radius;
      for (std::size_t j = 0; j < points->size(); ++j) {
        const float d = ((*points)[j] - image).norm();
        if (d < nearest) {
          nearest = d;
          best = static_cast<int>(j);
        }
      }
      return best;
    };
  }

 private:
  ss::Cloud cloud_;
  std::vector<std::vector<int>> neighbours_;
};

}  // namespace test_support
