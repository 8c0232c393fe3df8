#pragma once
// The scene's evidence (scene_evidence.h) as the graph cut sees it: reflections judged by its
// data term, scores by its smoothness links (paper eq. 13-14), free space by the occupancy map.
#include "symmetry_segmentation/occupancy.h"
#include "symmetry_segmentation/symmetry/scene_evidence.h"
#include "symmetry_segmentation/symmetry/symmetric_graph_cut.h"
#include "symmetry_segmentation/symmetry/symmetry_params.h"

namespace symmetry_segmentation {

class GraphEvidence : public SceneEvidence {
 public:
  /// Everything referenced must outlive this object.
  GraphEvidence(const SymmetricGraphCut& graph, const OccupancyMap& occupancy, const SymmetryFilterParams& filter)
      : graph_(graph), occupancy_(occupancy), filter_(filter) {}

  const Cloud& cloud() const override { return graph_.cloud(); }
  const std::vector<std::vector<int>>& neighbours() const override { return graph_.neighbours(); }
  ReflectionEvidence reflection(int index, const SymmetryPlane& plane) const override {
    return graph_.dataTerm(index, plane);
  }
  SegmentScores scores(const std::vector<int>& points, const SymmetryPlane& plane) const override {
    return graph_.scores(points, plane, filter_);
  }
  bool observedFree(const Eigen::Vector3f& point) const override {
    return occupancy_.classify(point) == Occupancy::Free;
  }

 private:
  const SymmetricGraphCut& graph_;
  const OccupancyMap& occupancy_;
  SymmetryFilterParams filter_;
};

}  // namespace symmetry_segmentation
