#pragma once
// What surrounds a real tabletop and the fixed generated set leaves out: a wall behind the
// table (sometimes with a shelf), the table's legs, the floor and clutter standing on it - all
// background (label 0), none of it an object - and prints on the objects themselves.

#include "symmetry_segmentation/synthetic/random.h"
#include "symmetry_segmentation/synthetic/scene_layout.h"
#include "symmetry_segmentation/synthetic/synthetic_world.h"

namespace symmetry_segmentation {
namespace synthetic {

/// Height of the table top above the floor in the rooms addRoom builds (m).
constexpr double kTableHeight = 0.75;

/// Adds the wall (0-12 cm behind the table's far edge, +y), an optional shelf on it, the legs,
/// the floor and 1-3 pieces of floor clutter beside the table to `world.background`.
void addRoom(SyntheticWorld& world, const TableSize& table, Random& random);

/// Gives each object a print with probability `share`: blocks of 1.5-5 cm in three inks.
void addPrints(SyntheticWorld& world, double share, Random& random);

}  // namespace synthetic
}  // namespace symmetry_segmentation
