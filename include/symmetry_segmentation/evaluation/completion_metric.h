#pragma once
// How well a segment completed by its symmetry stands for the whole object: the IoU of its box
// with the object's true box and the Chamfer distance of its points to the object's true
// surface, against the same figures for the visible points alone. Ground truth comes from
// make_scene (objects.yaml, objects_surface.ply; synthetic/object_shapes.h).

#include <cstddef>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "symmetry_segmentation/scene.h"
#include "symmetry_segmentation/segmentation_result.h"

namespace symmetry_segmentation {

/// One object's whole shape (scene frame).
struct TrueShape {
  int label = 0;
  std::string shape;  ///< make_scene's shape name (box, cylinder, ...); empty when not given.
  ObjectBox box;
  /// A solid of revolution about its box's z (cylinder, bottle, bowl, ball, cone, pot): any turn
  /// of its box about z is as true, and it is turned to the box it is compared with.
  bool round = false;
  std::vector<Eigen::Vector3f> surface;  ///< Samples of every side but the base.
};

/// The objects of `scene_dir`'s objects.yaml with their samples from objects_surface.ply; empty
/// when the scene has no objects.yaml. Throws InputError on a malformed or unreadable file.
std::vector<TrueShape> loadTrueShapes(const std::string& scene_dir);

/// Volume of the intersection over the union of two boxes, estimated from `samples` points
/// spread evenly (a fixed low-discrepancy sequence, so the estimate is repeatable) in each.
double boxIoU(const ObjectBox& a, const ObjectBox& b, int samples = 8000);

/// Symmetric Chamfer distance: the mean over both sets of the distance from each point to the
/// nearest point of the other set, halved. Infinite when either set is empty.
double chamferDistance(const std::vector<Eigen::Vector3f>& a, const std::vector<Eigen::Vector3f>& b);

/// One correctly segmented object (best segment IoU > 0.5 over labelled points).
struct CompletionScore {
  int label = 0;
  std::string shape;
  std::size_t added_points = 0;  ///< Points the completion added.
  double segment_iou = 0.0;
  double box_iou_visible = 0.0;    ///< The segment's box (visible points).
  double box_iou_completed = 0.0;  ///< The completion's box.
  double chamfer_visible = 0.0;    ///< m
  double chamfer_completed = 0.0;  ///< m
};

/// Scores every object of `shapes` some segment of `result` (with a box and a completion)
/// overlaps by IoU > 0.5 in `scene`'s labels.
std::vector<CompletionScore> scoreCompletion(const Scene& scene, const SegmentationResult& result,
                                             const std::vector<TrueShape>& shapes);

}  // namespace symmetry_segmentation
