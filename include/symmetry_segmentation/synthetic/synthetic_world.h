#pragma once
// Everything a virtual camera can see: an optional table (label 0) and the labelled objects.

#include <optional>
#include <vector>

#include "symmetry_segmentation/synthetic/synthetic_object.h"

namespace symmetry_segmentation {
namespace synthetic {

struct SyntheticWorld {
  std::optional<SyntheticObject> table;
  std::vector<SyntheticObject> objects;  ///< objects[i].label == i + 1 in generated worlds.
  /// Not on the table, not objects (label 0): walls, shelves, floor, clutter on the floor.
  std::vector<SyntheticObject> background;
};

struct WorldHit {
  double t = 0.0;
  Eigen::Vector3d point;
  Eigen::Vector3d normal;  ///< Unit, out of the material.
  int label = 0;
  Rgb color{{0, 0, 0}};
};

/// Nearest surface along the ray with t in [t_min, t_max] over the table and every object.
std::optional<WorldHit> rayIntersect(const SyntheticWorld& world, const Ray& ray, double t_min, double t_max);

}  // namespace synthetic
}  // namespace symmetry_segmentation
