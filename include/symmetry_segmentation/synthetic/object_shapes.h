#pragma once
// Each generated object's whole shape - every side, not only what the cameras saw - as ground
// truth for object completion: its box (objects.yaml) and samples of its surface
// (objects_surface.ply), both in the scene cloud's frame.

#include <string>
#include <vector>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include "symmetry_segmentation/synthetic/synthetic_object.h"
#include "symmetry_segmentation/synthetic/synthetic_world.h"

namespace symmetry_segmentation {
namespace synthetic {

/// Points of the object's surface where rays every `spacing` metres from the 17 grid directions
/// at or above the horizon first hit it (world frame). Its base on the table, which no robot
/// sees and no completion adds, is left out.
std::vector<Eigen::Vector3d> surfaceSamples(const SyntheticObject& object, double spacing);

/// Writes objects.yaml (per object: label, shape, box with centre, axes one per row, size) and
/// objects_surface.ply (x y z label, samples every `spacing` m) into `directory`, moved by
/// `world_to_scene` into the scene cloud's frame. Throws InputError when a file cannot be written.
void saveObjectShapes(const SyntheticWorld& world, const Eigen::Isometry3d& world_to_scene, const std::string& directory,
                      double spacing = 0.01);

}  // namespace synthetic
}  // namespace symmetry_segmentation
