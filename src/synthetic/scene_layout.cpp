#include "symmetry_segmentation/synthetic/scene_layout.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "symmetry_segmentation/synthetic/object_library.h"
#include "symmetry_segmentation/synthetic/table_placement.h"

namespace symmetry_segmentation {
namespace synthetic {
namespace {

/// Accumulates objects and stacking facts while a layout is built.
struct LayoutBuilder {
  SceneLayout layout;
  const std::vector<ObjectShape>* shapes = &objectShapes();  ///< Pool drawShapes draws from.

  int add(SyntheticObject object) {
    object.label = static_cast<int>(layout.world.objects.size()) + 1;
    object.color = colorForLabel(object.label);
    layout.world.objects.push_back(object);
    return object.label;
  }
  void addAll(const std::vector<SyntheticObject>& objects) {
    for (const auto& object : objects) add(object);
  }
};

TableRegion tableLimit(const TableSize& table) {
  const double margin = 0.05;  // keep objects off the edge
  TableRegion limit;
  limit.min = Eigen::Vector2d(-table.size_x / 2 + margin, -table.size_y / 2 + margin);
  limit.max = Eigen::Vector2d(table.size_x / 2 - margin, table.size_y / 2 - margin);
  return limit;
}

TableRegion region(double half_x, double half_y) {
  TableRegion r;
  r.min = Eigen::Vector2d(-half_x, -half_y);
  r.max = Eigen::Vector2d(half_x, half_y);
  return r;
}

/// `count` shapes, cycling through a shuffled list so mixes stay varied.
std::vector<ObjectShape> drawShapes(int count, Random& random, const std::vector<ObjectShape>& from) {
  std::vector<ObjectShape> pool = from;
  std::vector<ObjectShape> shapes;
  while (static_cast<int>(shapes.size()) < count) {
    for (std::size_t i = pool.size(); i > 1; --i) {
      std::swap(pool[i - 1], pool[static_cast<std::size_t>(random.uniformInt(0, static_cast<int>(i) - 1))]);
    }
    for (ObjectShape shape : pool) {
      if (static_cast<int>(shapes.size()) < count) shapes.push_back(shape);
    }
  }
  return shapes;
}

void layoutIsolated(LayoutBuilder& builder, TablePlacer& placer, Random& random) {
  for (ObjectShape shape : drawShapes(random.uniformInt(3, 5), random, *builder.shapes)) {
    SyntheticObject object = makeRandomObject(shape, random);
    placer.place(object, 0.1);
    builder.add(object);
  }
}

/// Boxes of equal depth pushed together along x, front faces flush.
std::vector<SyntheticObject> flushBoxRow(int count, Random& random) {
  const double depth = random.uniform(0.06, 0.12);
  std::vector<SyntheticObject> row;
  std::vector<double> widths;
  double total = 0.0;
  for (int i = 0; i < count; ++i) {
    widths.push_back(random.uniform(0.06, 0.12));
    total += widths.back();
  }
  double x = -total / 2;
  for (int i = 0; i < count; ++i) {
    SyntheticObject box = makeBox(widths[i], depth, random.uniform(0.07, 0.2));
    box.pose = uprightPose(x + widths[i] / 2, 0.0, 0.0, 0.0);
    x += widths[i];
    row.push_back(box);
  }
  return row;
}

void layoutTouching(LayoutBuilder& builder, TablePlacer& placer, Random& random) {
  // Each group runs roughly along x, i.e. side by side as the cameras (on the -y side) see
  // it, so the contacts are in view rather than hidden behind the objects.
  const double max_yaw = 0.35;
  auto row = flushBoxRow(3, random);
  placer.place(row, 0.06, max_yaw);
  builder.addAll(row);

  // A cylinder pushed against the end face of a box.
  SyntheticObject box = makeRandomBox(random, 0.07, 0.18);
  SyntheticObject cylinder = makeRandomObject(ObjectShape::Cylinder, random);
  const double radius = cylinder.local_max.x();
  const double half_y = box.local_max.y();
  const double side = random.chance(0.5) ? 1.0 : -1.0;
  cylinder.pose = uprightPose(side * (box.local_max.x() + radius), random.uniform(-0.5, 0.5) * half_y, 0.0, 0.0);
  std::vector<SyntheticObject> pair{box, cylinder};
  placer.place(pair, 0.06, max_yaw);
  builder.addAll(pair);

  // Two round objects touching each other.
  SyntheticObject first = makeRandomObject(random.chance(0.5) ? ObjectShape::Cylinder : ObjectShape::Bottle, random);
  SyntheticObject second = makeRandomObject(random.chance(0.5) ? ObjectShape::Cylinder : ObjectShape::Cone, random);
  const double r1 = first.local_max.x();
  const double r2 = second.local_max.x();
  second.pose = uprightPose(r1 + r2, 0.0, 0.0, 0.0);
  std::vector<SyntheticObject> round_pair{first, second};
  placer.place(round_pair, 0.06, max_yaw);
  builder.addAll(round_pair);
}

void layoutStacked(LayoutBuilder& builder, TablePlacer& placer, Random& random) {
  // A box on a box of the same footprint.
  const double size_x = random.uniform(0.08, 0.16);
  const double size_y = random.uniform(0.07, 0.13);
  SyntheticObject lower = makeBox(size_x, size_y, random.uniform(0.06, 0.14));
  SyntheticObject upper = makeBox(size_x, size_y, random.uniform(0.05, 0.1));
  upper.pose = uprightPose(0.0, 0.0, lower.height(), 0.0);
  std::vector<SyntheticObject> stack{lower, upper};
  placer.place(stack, 0.08);
  const int lower_label = builder.add(stack[0]);
  builder.layout.stacked.emplace_back(builder.add(stack[1]), lower_label);

  // A round object (cylinder, bowl or mug) on a wider, lower box.
  const ObjectShape top_shape =
      std::vector<ObjectShape>{ObjectShape::Cylinder, ObjectShape::Bowl, ObjectShape::Mug}[random.uniformInt(0, 2)];
  SyntheticObject top = makeRandomObject(top_shape, random);
  const double top_x = std::max(-top.local_min.x(), top.local_max.x());
  const double top_y = std::max(-top.local_min.y(), top.local_max.y());
  SyntheticObject base = makeBox(2 * top_x + random.uniform(0.02, 0.08), 2 * top_y + random.uniform(0.02, 0.06),
                                 random.uniform(0.05, 0.1));
  top.pose = uprightPose(0.0, 0.0, base.height(), random.uniform(-M_PI, M_PI) * 0.25);
  std::vector<SyntheticObject> second_stack{base, top};
  placer.place(second_stack, 0.08);
  const int base_label = builder.add(second_stack[0]);
  builder.layout.stacked.emplace_back(builder.add(second_stack[1]), base_label);

  // One object standing alone for contrast.
  SyntheticObject single = makeRandomObject(drawShapes(1, random, *builder.shapes).front(), random);
  placer.place(single, 0.08);
  builder.add(single);
}

void layoutOccluded(LayoutBuilder& builder, TablePlacer& placer, Random& random) {
  // A long, shallow box facing the cameras (which stand on the -y side), and a tall thin board
  // just in front of its middle: wide and tall enough that no camera on the arc sees over or
  // around it, so the box's visible surface falls apart into a left and a right piece.
  const double depth = random.uniform(0.045, 0.06);
  const double height = random.uniform(0.08, 0.13);
  SyntheticObject occluded = makeBox(random.uniform(0.22, 0.28), depth, height);
  const double x = random.uniform(-0.04, 0.04);
  const double y = 0.04;
  occluded.pose = uprightPose(x, y, 0.0, 0.0);

  const double gap = 0.008;
  const double board_thickness = random.uniform(0.012, 0.018);
  SyntheticObject occluder = makeBox(random.uniform(0.085, 0.095), board_thickness, height + random.uniform(0.13, 0.16));
  occluder.pose = uprightPose(x + random.uniform(-0.01, 0.01), y - depth / 2 - gap - board_thickness / 2, 0.0, 0.0);
  placer.reserve(occluded);
  placer.reserve(occluder);
  builder.layout.occluded_label = builder.add(occluded);
  builder.layout.occluder_label = builder.add(occluder);

  // Two unrelated objects beside them.
  for (ObjectShape shape : drawShapes(2, random, *builder.shapes)) {
    SyntheticObject object = makeRandomObject(shape, random);
    placer.place(object, 0.08);
    builder.add(object);
  }
}

void layoutNonConvex(LayoutBuilder& builder, TablePlacer& placer, Random& random) {
  std::vector<ObjectShape> shapes = {ObjectShape::Mug, ObjectShape::Bowl, ObjectShape::LShape, ObjectShape::UShape};
  if (random.chance(0.5)) shapes.push_back(random.chance(0.5) ? ObjectShape::Mug : ObjectShape::Bowl);
  for (ObjectShape shape : shapes) {
    SyntheticObject object = makeRandomObject(shape, random);
    placer.place(object, 0.06);
    builder.add(object);
  }
}

void layoutClutter(LayoutBuilder& builder, TablePlacer& placer, Random& random) {
  for (ObjectShape shape : drawShapes(random.uniformInt(8, 12), random, *builder.shapes)) {
    SyntheticObject object = makeRandomObject(shape, random);
    placer.place(object, random.uniform(0.005, 0.025));
    builder.add(object);
  }
}

/// Books and boards lying flat among the objects, where they fit; on a crowded table there
/// may be fewer than drawn.
void addBooks(LayoutBuilder& builder, TablePlacer& placer, int max_books, Random& random) {
  const int count = random.uniformInt(0, max_books);
  for (int i = 0; i < count; ++i) {
    SyntheticObject book = makeRandomObject(ObjectShape::Book, random);
    try {
      placer.place(book, random.uniform(0.01, 0.05));
    } catch (const std::runtime_error&) {
      continue;
    }
    builder.add(book);
  }
}

/// Centre of the objects' extent on the table, slightly above it.
Eigen::Vector3d layoutFocus(const SceneLayout& layout) {
  Eigen::Vector2d min = Eigen::Vector2d::Constant(1e9);
  Eigen::Vector2d max = Eigen::Vector2d::Constant(-1e9);
  for (const auto& object : layout.world.objects) {
    Eigen::Vector2d fmin, fmax;
    footprintBounds(object.worldFootprint(), fmin, fmax);
    min = min.cwiseMin(fmin);
    max = max.cwiseMax(fmax);
  }
  if (layout.world.objects.empty()) return Eigen::Vector3d(0.0, 0.0, 0.05);
  const Eigen::Vector2d centre = 0.5 * (min + max);
  return Eigen::Vector3d(centre.x(), centre.y(), 0.05);
}

}  // namespace

RealismOptions RealismOptions::realistic() {
  RealismOptions options;
  options.room = true;
  options.printed_share = 0.5;
  options.max_books = 2;
  options.more_shapes = true;
  options.shading = true;
  return options;
}

SceneLayout layoutScene(SceneKind kind, Random& random, const TableSize& table, const RealismOptions& realism) {
  LayoutBuilder builder;
  if (realism.more_shapes) builder.shapes = &moreObjectShapes();
  builder.layout.world.table = makeTable(table.size_x, table.size_y, table.thickness);
  const TableRegion limit = tableLimit(table);
  TableRegion start = region(0.28, 0.18);
  switch (kind) {
    case SceneKind::Isolated: start = region(0.4, 0.25); break;
    case SceneKind::Touching: start = region(0.38, 0.24); break;
    case SceneKind::Stacked: start = region(0.35, 0.22); break;
    case SceneKind::Occluded: start = region(0.4, 0.25); break;
    case SceneKind::NonConvex: start = region(0.35, 0.22); break;
    case SceneKind::Clutter: start = region(0.28, 0.18); break;
  }
  TablePlacer placer(start, limit, random);
  switch (kind) {
    case SceneKind::Isolated: layoutIsolated(builder, placer, random); break;
    case SceneKind::Touching: layoutTouching(builder, placer, random); break;
    case SceneKind::Stacked: layoutStacked(builder, placer, random); break;
    case SceneKind::Occluded: layoutOccluded(builder, placer, random); break;
    case SceneKind::NonConvex: layoutNonConvex(builder, placer, random); break;
    case SceneKind::Clutter: layoutClutter(builder, placer, random); break;
  }
  if (realism.max_books > 0) addBooks(builder, placer, realism.max_books, random);
  builder.layout.focus = layoutFocus(builder.layout);
  if (kind == SceneKind::Occluded) {
    // Centre the camera arc on the occluded object, which the occluder is designed around.
    const auto& occluded = builder.layout.world.objects[builder.layout.occluded_label - 1];
    builder.layout.focus.head<2>() = occluded.position().head<2>();
  }
  return builder.layout;
}

}  // namespace synthetic
}  // namespace symmetry_segmentation
