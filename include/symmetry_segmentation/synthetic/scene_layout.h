#pragma once
// Which objects stand where on the table for each scene kind, plus the facts about the layout
// that the ground truth checks rely on (which object is occluded, which stands on which).

#include <utility>
#include <vector>

#include "symmetry_segmentation/synthetic/random.h"
#include "symmetry_segmentation/synthetic/scene_kind.h"
#include "symmetry_segmentation/synthetic/synthetic_world.h"

namespace symmetry_segmentation {
namespace synthetic {

struct TableSize {
  double size_x = 1.2;
  double size_y = 0.8;
  double thickness = 0.04;
};

struct SceneLayout {
  SyntheticWorld world;  ///< Table (top at z = 0, centred at the origin) and labelled objects.
  Eigen::Vector3d focus = Eigen::Vector3d(0.0, 0.0, 0.05);  ///< Where the cameras look.
  int occluded_label = 0;  ///< Occluded kind: the object split by the occluder.
  int occluder_label = 0;
  std::vector<std::pair<int, int>> stacked;  ///< (upper label, lower label) pairs.
};

/// Lays out a scene of `kind`. Objects get labels 1..N and colours; all draws come from
/// `random`, so the layout is a function of its seed.
SceneLayout layoutScene(SceneKind kind, Random& random, const TableSize& table = {});

}  // namespace synthetic
}  // namespace symmetry_segmentation
