#pragma once
// Stage 4, cut (paper eq. 7-12): for each hypothesis not cut yet, the working-cloud points that
// belong to the object symmetric about its plane, by a graph cut over the 1 cm cloud (data term
// from where each point's reflection lands, convexity-weighted smoothness, symmetric-neighbour
// links), and the candidate's scores (eq. 13-14, segment_scores.cpp). The kd-tree, the
// smoothness graph and the point grid for reflection queries are built once per scene and
// shared by every hypothesis; segment() and scores() are const and safe to call from several
// threads, so hypotheses are cut in parallel and stored by index (any thread count, same result).

#include <memory>
#include <optional>
#include <vector>

#include <Eigen/Geometry>
#include <pcl/kdtree/kdtree_flann.h>

#include "symmetry_segmentation/occupancy.h"
#include "symmetry_segmentation/occupancy_grid.h"
#include "symmetry_segmentation/scene.h"
#include "symmetry_segmentation/segmentation_result.h"
#include "symmetry_segmentation/symmetry/point_grid.h"
#include "symmetry_segmentation/symmetry/reflection_data_term.h"
#include "symmetry_segmentation/symmetry/stage.h"
#include "symmetry_segmentation/symmetry/symmetry_params.h"

namespace symmetry_segmentation {

class SymmetricGraphCut {
 public:
  /// `cloud`: working cloud with oriented normals; `occupancy`: the scene's map (must outlive
  /// this object); `table`: the supporting plane, oriented toward the objects, and the table's
  /// fitted top if known.
  SymmetricGraphCut(Cloud::ConstPtr cloud, const OccupancyMap& occupancy,
                    std::optional<TableTop> table, const SymmetryCutParams& params);

  /// Foreground working-cloud indices (sorted) for `plane`: one connected object, the one holding
  /// most `anchor` points if any are given (see strongest_component.h).
  std::vector<int> segment(const SymmetryPlane& plane, const std::vector<int>& anchor = {}) const;

  /// Occlusion score (fraction of segment points whose reflection does not land in free space)
  /// and smoothness score (broken smooth links per segment point).
  SegmentScores scores(const std::vector<int>& segment, const SymmetryPlane& plane,
                       const SymmetryFilterParams& filter) const;

  /// The unary evidence of one point for `plane` (eq. 7-10; see reflection_data_term.h).
  ReflectionEvidence dataTerm(int index, const SymmetryPlane& plane) const;

  const Cloud& cloud() const { return *cloud_; }
  const pcl::KdTreeFLANN<PointT>& tree() const { return tree_; }
  /// k-NN smoothness neighbours of each point (the graph's edges, each listed from both ends).
  /// An isolated point has none.
  const std::vector<std::vector<int>>& neighbours() const { return neighbours_; }
  /// Whether point i has no other point within isolated_radius: a depth camera's flying pixel
  /// or speckle, never part of a segment.
  bool isolated(int i) const { return isolated_[i] != 0; }

 private:
  Cloud::ConstPtr cloud_;
  const OccupancyMap& occupancy_;
  std::unique_ptr<OccupancyGrid> occupancy_grid_;  ///< occupancy_ around the cloud, for the data term.
  std::optional<TableTop> table_;
  SymmetryCutParams params_;
  pcl::KdTreeFLANN<PointT> tree_;
  std::vector<std::vector<int>> neighbours_;
  std::vector<char> isolated_;  ///< Per point: no other point within isolated_radius.

  struct SmoothLink {
    int a = 0;
    int b = 0;
    float weight = 0.0f;  ///< eq. 11, lambda_smooth included.
  };
  std::vector<SmoothLink> smooth_links_;  ///< Each undirected k-NN link once (a < b).
  Eigen::AlignedBox3f cloud_box_;         ///< Lets far reflections skip the grid.
  PointGrid grid_;                        ///< Reflection queries (faster than tree_ for them).

  ReflectionDataTerm dataTermView() const;
};

/// The stage: a candidate per hypothesis not cut yet (scored when it has the filter's
/// min_segment_points).
class GraphCutStage : public Stage {
 public:
  explicit GraphCutStage(const SymmetryFilterParams& filter) : filter_(filter) {}
  void run(PipelineState& state) const override;

 private:
  SymmetryFilterParams filter_;
};

}  // namespace symmetry_segmentation
