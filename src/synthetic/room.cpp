#include "symmetry_segmentation/synthetic/room.h"

#include <algorithm>
#include <cmath>

#include "symmetry_segmentation/synthetic/object_library.h"

namespace symmetry_segmentation {
namespace synthetic {
namespace {

// The least gap between a chair's back and the table's end (m): a chair pushed in close.
constexpr double kChairClearance = 0.02;

SyntheticObject slab(const Eigen::Vector3d& min, const Eigen::Vector3d& max, const Rgb& color) {
  SyntheticObject object;
  object.shape = ObjectShape::Box;
  addPatch(object, BoxSolid{min, max});
  object.label = 0;
  object.color = color;
  return object;
}

uint8_t channel(Random& random, double low, double high) {
  return static_cast<uint8_t>(std::lround(random.uniform(low, high)));
}

Rgb randomColor(Random& random, double low = 30.0, double high = 230.0) {
  return Rgb{{channel(random, low, high), channel(random, low, high), channel(random, low, high)}};
}

/// A pale wall colour: near-grey with a slight tint.
Rgb wallColor(Random& random) {
  const double base = random.uniform(175.0, 235.0);
  return Rgb{{channel(random, base - 12, base + 12), channel(random, base - 12, base + 12),
              channel(random, base - 20, base + 5)}};
}

/// A box, bin or chair on the floor beside the table, at x beyond its end.
void addFloorClutter(SyntheticWorld& world, const TableSize& table, Random& random) {
  const double side = random.chance(0.5) ? 1.0 : -1.0;
  const double x = side * (table.size_x / 2 + random.uniform(0.1, 0.45));
  const double y = random.uniform(-table.size_y / 2, table.size_y / 2);
  const double floor_z = -kTableHeight;
  switch (random.uniformInt(0, 2)) {
    case 0: {  // carton
      const double sx = random.uniform(0.25, 0.5), sy = random.uniform(0.25, 0.45), sz = random.uniform(0.2, 0.6);
      world.background.push_back(slab({x - sx / 2, y - sy / 2, floor_z}, {x + sx / 2, y + sy / 2, floor_z + sz},
                                      randomColor(random, 90, 200)));
      break;
    }
    case 1: {  // waste bin
      SyntheticObject bin = makeCylinder(random.uniform(0.12, 0.18), random.uniform(0.3, 0.45));
      bin.pose = uprightPose(x, y, floor_z, 0.0);
      bin.label = 0;
      bin.color = randomColor(random);
      world.background.push_back(bin);
      break;
    }
    default: {  // chair: seat and back, seat a little below the table top
      const double seat_z = floor_z + random.uniform(0.42, 0.5);
      const double half = random.uniform(0.2, 0.24);
      const Rgb color = randomColor(random, 20, 160);
      // Its back rises over the table top: it stands clear of the table's end, never through it.
      // (Moved, not redrawn: every later draw stays as it was.)
      const double chair_x = side * std::max(std::fabs(x), table.size_x / 2 + half + kChairClearance);
      world.background.push_back(
          slab({chair_x - half, y - half, seat_z - 0.04}, {chair_x + half, y + half, seat_z}, color));
      world.background.push_back(slab({chair_x - half, y + half - 0.03, seat_z},
                                      {chair_x + half, y + half, seat_z + random.uniform(0.35, 0.5)}, color));
      break;
    }
  }
}

}  // namespace

void addRoom(SyntheticWorld& world, const TableSize& table, Random& random) {
  const double floor_z = -kTableHeight;
  const double wall_y = table.size_y / 2 + random.uniform(0.0, 0.12);
  world.background.push_back(slab({-3.0, wall_y, floor_z}, {3.0, wall_y + 0.1, 1.5}, wallColor(random)));
  if (random.chance(0.5)) {
    // A shelf board on the wall, above the table: a second horizontal surface, smaller and higher.
    const double height = random.uniform(0.35, 0.55);
    const double depth = random.uniform(0.15, 0.25);
    const double half_width = random.uniform(0.35, 0.7);
    const double x = random.uniform(-0.3, 0.3);
    world.background.push_back(slab({x - half_width, wall_y - depth, height - 0.02},
                                    {x + half_width, wall_y, height}, randomColor(random, 60, 220)));
  }
  world.background.push_back(slab({-4.0, -4.0, floor_z - 0.05}, {4.0, wall_y, floor_z}, randomColor(random, 60, 140)));
  const Rgb leg_color = world.table ? world.table->color : Rgb{{150, 115, 80}};
  for (double sx : {-1.0, 1.0}) {
    for (double sy : {-1.0, 1.0}) {
      const double x = sx * (table.size_x / 2 - 0.06);
      const double y = sy * (table.size_y / 2 - 0.06);
      world.background.push_back(
          slab({x - 0.025, y - 0.025, floor_z}, {x + 0.025, y + 0.025, -table.thickness}, leg_color));
    }
  }
  const int clutter = random.uniformInt(1, 3);
  for (int i = 0; i < clutter; ++i) addFloorClutter(world, table, random);
}

void addPrints(SyntheticWorld& world, double share, Random& random) {
  for (auto& object : world.objects) {
    // Always draw every number, so one object's print never shifts the next object's.
    const bool printed = random.chance(share);
    Print print;
    print.block = random.uniform(0.015, 0.05);
    print.ink_share = random.uniform(0.3, 0.6);
    for (auto& ink : print.inks) ink = randomColor(random);
    print.seed = static_cast<uint64_t>(random.uniformInt(0, 1 << 30));
    print.enabled = printed;
    object.print = print;
  }
}

}  // namespace synthetic
}  // namespace symmetry_segmentation
