#include "symmetry_segmentation/evaluation/ground_truth.h"

#include <cmath>
#include <regex>

#include <pcl/PointIndices.h>

#include "symmetry_segmentation/errors.h"
#include "symmetry_segmentation/evaluation/segmentation_metric.h"
#include "symmetry_segmentation/plane_fit.h"
#include "symmetry_segmentation/scene_io.h"

namespace symmetry_segmentation {

namespace {

constexpr std::uint32_t kFirstOsdObjectLabel = 20;

bool isOsdTableLabel(std::uint32_t label) { return label >= 1 && label <= 9; }

}  // namespace

std::vector<int> osdGroundTruth(const std::vector<std::uint32_t>& file_labels, bool parts) {
  std::vector<int> labels(file_labels.size(), 0);
  for (std::size_t i = 0; i < file_labels.size(); ++i) {
    const std::uint32_t label = file_labels[i];
    if (label < kFirstOsdObjectLabel || label > 0x7fffffffu) continue;
    labels[i] = static_cast<int>(parts ? label : label / 10);
  }
  return labels;
}

std::string osdCategory(const std::string& scene_name) {
  static const std::regex name("(learn|test)([0-9]{1,3})");
  std::smatch match;
  if (!std::regex_match(scene_name, match, name)) return "";
  const int number = std::stoi(match[2].str());
  // The ranges of mOSD's README (learn 0-44, test 0-65).
  if (match[1].str() == "learn") {
    if (number <= 16) return "boxes";
    if (number <= 24) return "stacked";
    if (number <= 32) return "occluded";
    if (number <= 44) return "cylindric";
    return "";
  }
  if (number <= 15) return "boxes";
  if (number <= 23) return "stacked";
  if (number <= 30) return "occluded";
  if (number <= 42) return "cylindric";
  if (number <= 54) return "mixed";
  if (number <= 65) return "complex";
  return "";
}

void ignoreNearPlane(const Cloud& cloud, const PlaneCoefficients& plane, double band, std::vector<int>& labels) {
  const float norm = plane.head<3>().norm();
  if (!(norm > 0.0f) || labels.size() != cloud.size()) return;
  for (std::size_t i = 0; i < cloud.size(); ++i) {
    const PointT& point = cloud[i];
    if (!std::isfinite(point.x) || !std::isfinite(point.y) || !std::isfinite(point.z)) continue;
    const float distance = std::abs(plane.head<3>().dot(point.getVector3fMap()) + plane[3]) / norm;
    if (distance <= band) labels[i] = kIgnoredLabel;
  }
}

PlaneCoefficients fitOsdTablePlane(const std::string& source, const Cloud& cloud,
                                   const std::vector<std::uint32_t>& file_labels) {
  auto table = std::make_shared<Cloud>();
  for (std::size_t i = 0; i < cloud.size() && i < file_labels.size(); ++i) {
    const PointT& point = cloud[i];
    if (isOsdTableLabel(file_labels[i]) && std::isfinite(point.x) && std::isfinite(point.y) && std::isfinite(point.z))
      table->push_back(point);
  }
  if (table->size() < 3) throw InputError(source, "--table-band: fewer than 3 table-labelled points");
  pcl::PointIndices inliers;
  const auto plane = fitLargestPlane(table, 0.02, 500, inliers);
  if (!plane) throw InputError(source, "--table-band: no plane fits the table-labelled points");
  return *plane;
}

Scene loadLabelledScene(const std::string& path, const GroundTruthOptions& options) {
  Scene scene = loadScene(path);
  const bool osd = !scene.hasLabels() && !scene.file_labels.empty();
  if (osd) {
    scene.labels = osdGroundTruth(scene.file_labels, options.osd_parts);
    if (scene.kind.empty()) scene.kind = osdCategory(scene.name);
  }
  if (options.table_band > 0.0 && scene.hasLabels()) {
    PlaneCoefficients plane;
    if (osd) {
      plane = fitOsdTablePlane(path, *scene.cloud, scene.file_labels);
    } else if (scene.table_plane) {
      plane = *scene.table_plane;
    } else {
      throw InputError(path, "--table-band: no table-labelled points and no table_plane.txt");
    }
    ignoreNearPlane(*scene.cloud, plane, options.table_band, scene.labels);
  }
  return scene;
}

}  // namespace symmetry_segmentation
