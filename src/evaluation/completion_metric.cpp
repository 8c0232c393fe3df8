// Completion against the objects' whole shapes (see the header).
#include "symmetry_segmentation/evaluation/completion_metric.h"

#include <cmath>
#include <limits>
#include <map>
#include <set>

#include <boost/filesystem.hpp>
#include <pcl/io/ply_io.h>
#include <pcl/kdtree/kdtree_flann.h>
#include <pcl/point_types.h>
#include <yaml-cpp/yaml.h>

#include "symmetry_segmentation/errors.h"
#include "symmetry_segmentation/object_box.h"
#include "symmetry_segmentation/symmetry/completion.h"

namespace symmetry_segmentation {
namespace {

Eigen::Vector3f vector3(const YAML::Node& node, const std::string& path, const std::string& what) {
  if (!node || !node.IsSequence() || node.size() != 3) throw InputError(path, what + " needs 3 numbers");
  Eigen::Vector3f v;
  for (int i = 0; i < 3; ++i) {
    v[i] = node[i].as<float>();
    if (!std::isfinite(v[i])) throw InputError(path, what + " must be finite");
  }
  return v;
}

/// Point `i` of a 3D low-discrepancy sequence in the unit cube (R3, Roberts 2018).
Eigen::Vector3d unitSample(int i) {
  static const double g = 1.2207440846057596;  // root of x^4 = x + 1
  static const Eigen::Vector3d alpha(1.0 / g, 1.0 / (g * g), 1.0 / (g * g * g));
  const Eigen::Vector3d value = Eigen::Vector3d::Constant(0.5) + static_cast<double>(i + 1) * alpha;
  return value.unaryExpr([](double x) { return x - std::floor(x); });
}

bool contains(const ObjectBox& box, const Eigen::Vector3d& p) {
  const Eigen::Vector3d local = box.axes.cast<double>().transpose() * (p - box.center.cast<double>());
  return (local.cwiseAbs().array() <= 0.5 * box.size.cast<double>().array() + 1e-9).all();
}

Eigen::Vector3d pointIn(const ObjectBox& box, int i) {
  const Eigen::Vector3d unit = unitSample(i) - Eigen::Vector3d::Constant(0.5);
  return box.center.cast<double>() + box.axes.cast<double>() * unit.cwiseProduct(box.size.cast<double>());
}

double meanNearest(const std::vector<Eigen::Vector3f>& from, const std::vector<Eigen::Vector3f>& to) {
  auto cloud = std::make_shared<pcl::PointCloud<pcl::PointXYZ>>();
  for (const auto& p : to) cloud->push_back(pcl::PointXYZ(p.x(), p.y(), p.z()));
  pcl::KdTreeFLANN<pcl::PointXYZ> tree;
  tree.setInputCloud(cloud);
  std::vector<int> index(1);
  std::vector<float> squared(1);
  double sum = 0.0;
  for (const auto& p : from) {
    if (tree.nearestKSearch(pcl::PointXYZ(p.x(), p.y(), p.z()), 1, index, squared) > 0) sum += std::sqrt(squared[0]);
  }
  return sum / static_cast<double>(from.size());
}

/// The true box, for a round shape turned about its z so that its x lies along the horizontal
/// part of the one axis of `other` nearest to horizontal.
ObjectBox trueBoxFacing(const TrueShape& shape, const ObjectBox& other) {
  ObjectBox box = shape.box;
  if (!shape.round) return box;
  const Eigen::Vector3f z = box.axes.col(2).normalized();
  Eigen::Vector3f best = Eigen::Vector3f::Zero();
  for (int k = 0; k < 3; ++k) {
    const Eigen::Vector3f horizontal = other.axes.col(k) - other.axes.col(k).dot(z) * z;
    if (horizontal.norm() > best.norm()) best = horizontal;
  }
  if (!(best.norm() > 1e-3f)) return box;
  box.axes.col(0) = best.normalized();
  box.axes.col(1) = z.cross(box.axes.col(0));
  box.axes.col(2) = z;
  return box;
}

}  // namespace

std::vector<TrueShape> loadTrueShapes(const std::string& scene_dir) {
  const std::string yaml_path = scene_dir + "/objects.yaml";
  std::vector<TrueShape> shapes;
  if (!boost::filesystem::exists(yaml_path)) return shapes;
  std::map<int, std::size_t> by_label;
  try {
    const YAML::Node root = YAML::LoadFile(yaml_path);
    const YAML::Node objects = root["objects"];
    if (!objects || !objects.IsSequence()) throw InputError(yaml_path, "'objects' must be a list");
    for (const YAML::Node& object : objects) {
      TrueShape shape;
      shape.label = object["label"].as<int>();
      static const std::set<std::string> round = {"cylinder", "bottle", "bowl", "ball", "cone", "pot"};
      if (object["shape"]) shape.shape = object["shape"].as<std::string>();
      shape.round = round.count(shape.shape) > 0;
      if (shape.label <= 0 || by_label.count(shape.label)) throw InputError(yaml_path, "labels must be positive and distinct");
      const YAML::Node box = object["box"];
      if (!box || !box.IsMap()) throw InputError(yaml_path, "each object needs a 'box'");
      shape.box.center = vector3(box["center"], yaml_path, "box center");
      shape.box.size = vector3(box["size"], yaml_path, "box size");
      const YAML::Node axes = box["axes"];
      if (!axes || !axes.IsSequence() || axes.size() != 3) throw InputError(yaml_path, "box axes need 3 rows");
      for (int k = 0; k < 3; ++k) shape.box.axes.col(k) = vector3(axes[k], yaml_path, "box axis");
      const std::string problem = boxProblem(shape.box);
      if (!problem.empty()) throw InputError(yaml_path, problem);
      by_label[shape.label] = shapes.size();
      shapes.push_back(std::move(shape));
    }
  } catch (const YAML::Exception& e) {
    throw InputError(yaml_path, std::string("invalid YAML: ") + e.what());
  }
  const std::string ply_path = scene_dir + "/objects_surface.ply";
  if (!boost::filesystem::exists(ply_path)) return shapes;
  pcl::PointCloud<pcl::PointXYZL> surface;
  if (pcl::io::loadPLYFile(ply_path, surface) != 0) throw InputError(ply_path, "cannot read surface samples");
  for (const auto& p : surface.points) {
    const auto it = by_label.find(static_cast<int>(p.label));
    if (it != by_label.end()) shapes[it->second].surface.emplace_back(p.x, p.y, p.z);
  }
  return shapes;
}

double boxIoU(const ObjectBox& a, const ObjectBox& b, int samples) {
  const double volume_a = static_cast<double>(a.size.prod());
  const double volume_b = static_cast<double>(b.size.prod());
  if (!(volume_a > 0.0) || !(volume_b > 0.0) || samples <= 0) return 0.0;
  int a_in_b = 0, b_in_a = 0;
  for (int i = 0; i < samples; ++i) {
    a_in_b += contains(b, pointIn(a, i)) ? 1 : 0;
    b_in_a += contains(a, pointIn(b, i)) ? 1 : 0;
  }
  // Two estimates of the intersection's volume, one from each box; their mean.
  const double intersection = 0.5 * (volume_a * a_in_b + volume_b * b_in_a) / samples;
  return intersection / (volume_a + volume_b - intersection);
}

double chamferDistance(const std::vector<Eigen::Vector3f>& a, const std::vector<Eigen::Vector3f>& b) {
  if (a.empty() || b.empty()) return std::numeric_limits<double>::infinity();
  return 0.5 * (meanNearest(a, b) + meanNearest(b, a));
}

constexpr float kChamferCell = 0.01f;  // the working resolution, as the added points

std::vector<CompletionScore> scoreCompletion(const Scene& scene, const SegmentationResult& result,
                                             const std::vector<TrueShape>& shapes) {
  std::vector<CompletionScore> scores;
  if (!scene.cloud || scene.labels.size() != scene.cloud->size()) return scores;
  for (const TrueShape& shape : shapes) {
    std::size_t object_size = 0;
    for (int label : scene.labels) object_size += label == shape.label ? 1 : 0;
    if (object_size == 0 || shape.surface.empty()) continue;
    const Segment* best = nullptr;
    double best_iou = 0.0;
    for (const Segment& segment : result.segments) {
      std::size_t common = 0, labelled = 0;
      for (int index : segment.indices) {
        if (scene.labels[index] < 0) continue;
        ++labelled;
        common += scene.labels[index] == shape.label ? 1 : 0;
      }
      const double iou = static_cast<double>(common) / static_cast<double>(labelled + object_size - common);
      if (iou > best_iou) {
        best_iou = iou;
        best = &segment;
      }
    }
    if (!best || best_iou <= 0.5 || !best->box || !best->completion) continue;
    std::vector<Eigen::Vector3f> visible;
    for (int index : best->indices) visible.push_back(scene.cloud->points[index].getVector3fMap());
    // The visible points of a fused cloud lie a few millimetres apart, the added ones a working
    // voxel apart: one per cell, so that the Chamfer means weigh both alike.
    visible = onePerCell(visible, kChamferCell);
    std::vector<Eigen::Vector3f> completed = visible;
    completed.insert(completed.end(), best->completion->points.begin(), best->completion->points.end());
    CompletionScore score;
    score.label = shape.label;
    score.shape = shape.shape;
    score.added_points = best->completion->points.size();
    score.segment_iou = best_iou;
    score.box_iou_visible = boxIoU(*best->box, trueBoxFacing(shape, *best->box));
    score.box_iou_completed = boxIoU(best->completion->box, trueBoxFacing(shape, best->completion->box));
    score.chamfer_visible = chamferDistance(visible, shape.surface);
    score.chamfer_completed = chamferDistance(completed, shape.surface);
    scores.push_back(score);
  }
  return scores;
}

}  // namespace symmetry_segmentation
