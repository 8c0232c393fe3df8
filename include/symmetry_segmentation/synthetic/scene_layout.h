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

/// What real scenes have and the fixed generated set leaves out. All off by default, so the
/// fixed set stays bit-identical; RealismOptions::realistic() turns everything on.
struct RealismOptions {
  bool room = false;           ///< Wall (sometimes a shelf) behind the table, floor, floor clutter.
  double printed_share = 0.0;  ///< Share of objects wearing a print (0..1).
  int max_books = 0;           ///< Up to this many thin objects lying flat (books, boards).
  bool more_shapes = false;    ///< Balls and pots among the shapes drawn.
  bool shading = false;        ///< Colours darken as surfaces turn from the light.

  static RealismOptions realistic();
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
/// `realism` adds books and more shapes to the layout (the room and prints are added by
/// addRoom / addPrints); with it all off, the layout is the fixed set's.
SceneLayout layoutScene(SceneKind kind, Random& random, const TableSize& table = {},
                        const RealismOptions& realism = {});

}  // namespace synthetic
}  // namespace symmetry_segmentation
