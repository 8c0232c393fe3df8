#include "symmetry_segmentation/synthetic/object_library.h"

#include <cmath>

namespace symmetry_segmentation {
namespace synthetic {
namespace {

BoxSolid boxBetween(double x0, double y0, double z0, double x1, double y1, double z1) {
  return BoxSolid{Eigen::Vector3d(x0, y0, z0), Eigen::Vector3d(x1, y1, z1)};
}

SyntheticObject startObject(ObjectShape shape) {
  SyntheticObject object;
  object.shape = shape;
  return object;
}

}  // namespace

SyntheticObject makeBox(double size_x, double size_y, double size_z) {
  SyntheticObject object = startObject(ObjectShape::Box);
  addPatch(object, boxBetween(-size_x / 2, -size_y / 2, 0.0, size_x / 2, size_y / 2, size_z));
  return object;
}

SyntheticObject makeCylinder(double radius, double height) {
  SyntheticObject object = startObject(ObjectShape::Cylinder);
  addPatch(object, CylinderSide{radius, 0.0, height, true});
  addPatch(object, Annulus{height, 0.0, radius, true});
  addPatch(object, Annulus{0.0, 0.0, radius, false});
  return object;
}

SyntheticObject makeCone(double radius, double height) {
  SyntheticObject object = startObject(ObjectShape::Cone);
  addPatch(object, FrustumSide{0.0, height, radius, 0.0});
  addPatch(object, Annulus{0.0, 0.0, radius, false});
  return object;
}

SyntheticObject makeBottle(const BottleSize& size) {
  SyntheticObject object = startObject(ObjectShape::Bottle);
  const double shoulder_top = size.body_height + size.shoulder_height;
  const double top = shoulder_top + size.neck_height;
  addPatch(object, CylinderSide{size.body_radius, 0.0, size.body_height, true});
  addPatch(object, FrustumSide{size.body_height, shoulder_top, size.body_radius, size.neck_radius});
  addPatch(object, CylinderSide{size.neck_radius, shoulder_top, top, true});
  addPatch(object, Annulus{top, 0.0, size.neck_radius, true});
  addPatch(object, Annulus{0.0, 0.0, size.body_radius, false});
  return object;
}

SyntheticObject makeBowl(double radius, double height, double wall) {
  SyntheticObject object = startObject(ObjectShape::Bowl);
  // Sphere centred at the rim height, so the rim is the sphere's equator and the table cuts a
  // flat foot off the bottom.
  const Eigen::Vector3d centre(0.0, 0.0, height);
  const double inner_radius = radius - wall;
  const double floor_z = std::min(wall, 0.5 * height);
  addPatch(object, SphereZone{centre, radius, 0.0, height, true});
  addPatch(object, SphereZone{centre, inner_radius, floor_z, height, false});
  const double foot = std::sqrt(std::max(0.0, radius * radius - height * height));
  addPatch(object, Annulus{0.0, 0.0, foot, false});
  const double dz = height - floor_z;
  const double floor_radius = std::sqrt(std::max(0.0, inner_radius * inner_radius - dz * dz));
  if (floor_radius > 0.0) addPatch(object, Annulus{floor_z, 0.0, floor_radius, true});
  addPatch(object, Annulus{height, inner_radius, radius, true});
  return object;
}

SyntheticObject makeMug(const MugSize& size) {
  SyntheticObject object = startObject(ObjectShape::Mug);
  const double inner = size.radius - size.wall;
  addPatch(object, CylinderSide{size.radius, 0.0, size.height, true});
  addPatch(object, CylinderSide{inner, size.bottom, size.height, false});
  addPatch(object, Annulus{size.bottom, 0.0, inner, true});
  addPatch(object, Annulus{size.height, inner, size.radius, true});
  addPatch(object, Annulus{0.0, 0.0, size.radius, false});
  // Handle: two arms starting inside the wall (hidden there) and a vertical bar joining them.
  const double x0 = size.radius - 0.5 * size.wall;
  const double x1 = size.radius + size.handle_reach;
  const double hw = 0.5 * size.handle_width;
  const double th = size.handle_thickness;
  const double z_top = 0.85 * size.height;
  const double z_bottom = 0.2 * size.height;
  addPatch(object, boxBetween(x0, -hw, z_top - th, x1, hw, z_top));
  addPatch(object, boxBetween(x0, -hw, z_bottom, x1, hw, z_bottom + th));
  addPatch(object, boxBetween(x1 - th, -hw, z_bottom, x1, hw, z_top));
  return object;
}

SyntheticObject makeLShape(double length, double width, double thickness, double height) {
  SyntheticObject object = startObject(ObjectShape::LShape);
  const double x0 = -length / 2;
  addPatch(object, boxBetween(x0, -width / 2, 0.0, length / 2, width / 2, thickness));
  addPatch(object, boxBetween(x0, -width / 2, thickness, x0 + thickness, width / 2, height));
  return object;
}

SyntheticObject makeUShape(double length, double width, double thickness, double height) {
  SyntheticObject object = startObject(ObjectShape::UShape);
  const double x0 = -length / 2;
  const double x1 = length / 2;
  addPatch(object, boxBetween(x0, -width / 2, 0.0, x1, width / 2, thickness));
  addPatch(object, boxBetween(x0, -width / 2, thickness, x0 + thickness, width / 2, height));
  addPatch(object, boxBetween(x1 - thickness, -width / 2, thickness, x1, width / 2, height));
  return object;
}

SyntheticObject makeBall(double radius) {
  SyntheticObject object = startObject(ObjectShape::Ball);
  addPatch(object, SphereZone{Eigen::Vector3d(0.0, 0.0, radius), radius, 0.0, 2.0 * radius, true});
  return object;
}

SyntheticObject makePot(double bottom_radius, double top_radius, double height) {
  SyntheticObject object = startObject(ObjectShape::Pot);
  addPatch(object, FrustumSide{0.0, height, bottom_radius, top_radius});
  addPatch(object, Annulus{height, 0.0, top_radius, true});
  addPatch(object, Annulus{0.0, 0.0, bottom_radius, false});
  return object;
}

SyntheticObject makeBook(double length, double width, double thickness) {
  SyntheticObject object = makeBox(length, width, thickness);
  object.shape = ObjectShape::Book;
  return object;
}

SyntheticObject makeTable(double size_x, double size_y, double thickness) {
  SyntheticObject object = startObject(ObjectShape::Table);
  addPatch(object, boxBetween(-size_x / 2, -size_y / 2, -thickness, size_x / 2, size_y / 2, 0.0));
  object.label = 0;
  object.color = Rgb{{150, 115, 80}};
  return object;
}

SyntheticObject makeRandomBox(Random& random, double min_size, double max_size) {
  const double x = random.uniform(min_size, max_size);
  const double y = random.uniform(min_size, std::min(max_size, 0.2));
  const double z = random.uniform(min_size, max_size);
  return makeBox(x, y, z);
}

SyntheticObject makeRandomObject(ObjectShape shape, Random& random) {
  switch (shape) {
    case ObjectShape::Box: return makeRandomBox(random, 0.06, 0.22);
    case ObjectShape::Cylinder: {
      const double radius = random.uniform(0.03, 0.065);
      return makeCylinder(radius, random.uniform(0.07, 0.24));
    }
    case ObjectShape::Cone: {
      const double radius = random.uniform(0.04, 0.075);
      return makeCone(radius, random.uniform(0.09, 0.2));
    }
    case ObjectShape::Bottle: {
      BottleSize size;
      size.body_radius = random.uniform(0.03, 0.045);
      size.body_height = random.uniform(0.1, 0.17);
      size.shoulder_height = random.uniform(0.03, 0.05);
      size.neck_radius = random.uniform(0.012, 0.018);
      size.neck_height = random.uniform(0.03, 0.06);
      return makeBottle(size);
    }
    case ObjectShape::Bowl: {
      const double radius = random.uniform(0.065, 0.1);
      return makeBowl(radius, radius * random.uniform(0.55, 0.75), random.uniform(0.005, 0.008));
    }
    case ObjectShape::Mug: {
      MugSize size;
      size.radius = random.uniform(0.037, 0.05);
      size.height = random.uniform(0.085, 0.12);
      size.wall = random.uniform(0.005, 0.007);
      size.handle_reach = random.uniform(0.025, 0.035);
      size.handle_width = random.uniform(0.014, 0.02);
      return makeMug(size);
    }
    case ObjectShape::LShape: {
      const double length = random.uniform(0.12, 0.24);
      return makeLShape(length, random.uniform(0.06, 0.12), random.uniform(0.025, 0.04),
                        random.uniform(0.08, 0.18));
    }
    case ObjectShape::UShape: {
      const double length = random.uniform(0.14, 0.26);
      return makeUShape(length, random.uniform(0.06, 0.12), random.uniform(0.025, 0.04),
                        random.uniform(0.08, 0.16));
    }
    case ObjectShape::Ball: return makeBall(random.uniform(0.03, 0.07));
    case ObjectShape::Pot: {
      const double bottom = random.uniform(0.03, 0.055);
      return makePot(bottom, bottom * random.uniform(1.15, 1.45), random.uniform(0.06, 0.14));
    }
    case ObjectShape::Book: {
      // Lying flat: books, boards, boxes of tea - thin enough to look like a bump on the table.
      const double length = random.uniform(0.14, 0.3);
      return makeBook(length, length * random.uniform(0.55, 0.85), random.uniform(0.012, 0.045));
    }
    case ObjectShape::Table: break;
  }
  return makeRandomBox(random, 0.06, 0.22);
}

const std::vector<ObjectShape>& objectShapes() {
  static const std::vector<ObjectShape> shapes = {
      ObjectShape::Box,  ObjectShape::Cylinder, ObjectShape::Bottle, ObjectShape::Bowl,
      ObjectShape::Mug,  ObjectShape::Cone,     ObjectShape::LShape, ObjectShape::UShape};
  return shapes;
}

const std::vector<ObjectShape>& moreObjectShapes() {
  static const std::vector<ObjectShape> shapes = [] {
    std::vector<ObjectShape> all = objectShapes();
    all.insert(all.end(), {ObjectShape::Ball, ObjectShape::Pot});
    return all;
  }();
  return shapes;
}

Rgb colorForLabel(int label) {
  static const Rgb palette[] = {{{200, 40, 40}},  {{40, 120, 200}}, {{240, 190, 30}}, {{60, 170, 80}},
                                {{150, 70, 190}}, {{240, 120, 30}}, {{30, 180, 180}}, {{220, 90, 150}},
                                {{120, 120, 40}}, {{90, 60, 40}},   {{230, 230, 230}}, {{70, 70, 160}}};
  if (label <= 0) return Rgb{{150, 115, 80}};
  return palette[(label - 1) % (sizeof(palette) / sizeof(palette[0]))];
}

}  // namespace synthetic
}  // namespace symmetry_segmentation
