// Scene directories: which files make a scene, and writing one back out.
#include "symmetry_segmentation/scene_io.h"

#include <algorithm>
#include <cctype>

#include <fstream>
#include <iomanip>

#include <boost/filesystem.hpp>
#include <octomap/OcTree.h>
#include <pcl/common/io.h>
#include <pcl/io/pcd_io.h>
#include <pcl/io/ply_io.h>
#include <yaml-cpp/yaml.h>

namespace symmetry_segmentation {
namespace fs = boost::filesystem;
namespace {

std::string firstExisting(const fs::path& dir, std::initializer_list<const char*> names) {
  for (const char* name : names) {
    boost::system::error_code ec;
    if (fs::exists(dir / name, ec)) return (dir / name).string();
  }
  return {};
}

Eigen::Vector3f sensorOrigin(const std::string& path, const YAML::Node& node) {
  if (!node.IsSequence() || node.size() != 3) throw InputError(path, "each sensor origin needs 3 numbers");
  Eigen::Vector3f origin;
  for (int i = 0; i < 3; ++i) {
    if (!node[i].IsScalar()) throw InputError(path, "each sensor origin needs 3 numbers");
    origin[i] = node[i].as<float>();  // throws on text, which the caller reports
  }
  if (!origin.allFinite()) throw InputError(path, "sensor origins must be finite");
  return origin;
}

Eigen::Vector3f upDirection(const std::string& path, const YAML::Node& node) {
  if (!node.IsSequence() || node.size() != 3) throw InputError(path, "'up' needs 3 numbers [x, y, z]");
  Eigen::Vector3f up;
  for (int i = 0; i < 3; ++i) {
    if (!node[i].IsScalar()) throw InputError(path, "'up' needs 3 numbers [x, y, z]");
    up[i] = node[i].as<float>();
  }
  return checkedUpDirection(up, path);
}

// scene_info.yaml is written by make_scene; hand edits must still fail with one line.
void loadSceneInfo(const std::string& path, Scene& scene) {
  try {
    const YAML::Node info = YAML::LoadFile(path);
    if (!info.IsMap()) throw InputError(path, "expected a map with 'kind' and 'sensor_origins'");
    if (info["kind"]) {
      if (!info["kind"].IsScalar()) throw InputError(path, "'kind' must be a single word");
      scene.kind = info["kind"].as<std::string>();
      const bool word = !scene.kind.empty() && std::all_of(scene.kind.begin(), scene.kind.end(), [](char c) {
        return std::isalnum(static_cast<unsigned char>(c)) || c == '_' || c == '-';
      });
      if (!word) throw InputError(path, "'kind' must be a single word (letters, digits, '_', '-')");
      // The evaluator's total row is called "overall"; a scene kind of that name would merge
      // into it. ("unknown" is what scenes without a kind are grouped as, so it may be given.)
      if (scene.kind == "overall") throw InputError(path, "'kind' must not be 'overall' (reserved for the total)");
    }
    if (info["up"]) scene.up = upDirection(path, info["up"]);
    if (info["sensor_origins"]) {
      const YAML::Node list = info["sensor_origins"];
      if (!list.IsSequence() || list.size() == 0) {
        throw InputError(path, "'sensor_origins' must be a non-empty list of [x, y, z]");
      }
      std::vector<Eigen::Vector3f> origins;
      for (const auto& origin : list) origins.push_back(sensorOrigin(path, origin));
      scene.sensor_origins = origins;  // the generator's list is more complete than the PLY's one
    }
  } catch (const YAML::Exception& e) {
    throw InputError(path, std::string("invalid YAML: ") + e.what());
  }
}

}  // namespace

Eigen::Vector3f checkedUpDirection(const Eigen::Vector3f& up, const std::string& source) {
  // Normalised in double after scaling by the largest component: in float a component of 1e20
  // squares to inf and the "unit" vector came out zero.
  const Eigen::Vector3d direction = up.cast<double>();
  const double scale = direction.cwiseAbs().maxCoeff();
  if (!direction.allFinite() || !(scale > 1e-6)) throw InputError(source, "the up direction must be finite and not zero");
  return (direction / scale).normalized().cast<float>();
}

Scene loadScene(const std::string& path, const SceneLoadOptions& options) {
  Scene scene;
  boost::system::error_code ec;
  if (!fs::exists(path, ec)) throw InputError(path, "no such file or directory");
  const fs::path scene_path(path);
  if (!fs::is_directory(scene_path, ec)) {
    scene.name = scene_path.stem().string();
    loadCloudFile(path, scene);
    return scene;
  }

  scene.name = fs::canonical(scene_path, ec).filename().string();
  if (scene.name.empty()) scene.name = scene_path.filename().string();
  const std::string cloud_path = firstExisting(scene_path, {"cloud.ply", "cloud.pcd"});
  if (cloud_path.empty()) throw InputError(path, "scene directory has no cloud.ply or cloud.pcd");
  loadCloudFile(cloud_path, scene);

  const std::string info_path = firstExisting(scene_path, {"scene_info.yaml"});
  if (!info_path.empty()) loadSceneInfo(info_path, scene);

  if (options.load_occupancy) {
    const std::string map_path = firstExisting(scene_path, {"occupancy.bt", "occupancy.ot"});
    if (!map_path.empty()) scene.occupancy = loadOctomapFile(map_path);
  }
  const std::string plane_path = firstExisting(scene_path, {"table_plane.txt"});
  if (!plane_path.empty()) scene.table_plane = loadPlaneFile(plane_path);
  if (options.load_labels) {
    const std::string labels_path = firstExisting(scene_path, {"labels.txt"});
    if (!labels_path.empty()) scene.labels = loadLabelsFile(labels_path, scene.cloud->size());
  }
  return scene;
}

void saveScene(const Scene& scene, const std::string& directory) {
  if (!scene.cloud || scene.cloud->empty()) throw InputError(directory, "refusing to save an empty scene");
  boost::system::error_code ec;
  fs::create_directories(directory, ec);
  if (ec) throw InputError(directory, "cannot create directory: " + ec.message());
  const fs::path dir(directory);

  Eigen::Vector4f origin = Eigen::Vector4f::Zero();
  if (!scene.sensor_origins.empty()) origin.head<3>() = scene.sensor_origins[0];
  // A cloud file of the other format left from an earlier scene would be read instead.
  for (const char* name : {"cloud.ply", "cloud.pcd"}) fs::remove(dir / name, ec);
  if (scene.cloud->isOrganized()) {
    // An organized frame keeps its pixel layout (and NaN holes) in PCD; like a camera's cloud
    // it has no normals unless the scene has them.
    const std::string cloud_path = (dir / "cloud.pcd").string();
    int status = 0;
    if (scene.has_normals) {
      Cloud cloud = *scene.cloud;
      cloud.sensor_origin_ = origin;
      status = pcl::io::savePCDFileBinaryCompressed(cloud_path, cloud);
    } else {
      pcl::PointCloud<pcl::PointXYZRGB> cloud;
      pcl::copyPointCloud(*scene.cloud, cloud);
      cloud.sensor_origin_ = origin;
      status = pcl::io::savePCDFileBinaryCompressed(cloud_path, cloud);
    }
    if (status != 0) throw InputError(cloud_path, "cannot write cloud");
  } else {
    Cloud cloud = *scene.cloud;
    cloud.sensor_origin_ = origin;
    const std::string cloud_path = (dir / "cloud.ply").string();
    if (pcl::io::savePLYFileBinary(cloud_path, cloud) != 0) throw InputError(cloud_path, "cannot write cloud");
  }

  if (scene.occupancy) {
    const std::string map_path = (dir / "occupancy.bt").string();
    std::ofstream map_file(map_path, std::ios::binary);  // the stream overload does not chat on stderr
    if (!map_file || !scene.occupancy->writeBinaryConst(map_file) || !map_file.flush()) {
      throw InputError(map_path, "cannot write OctoMap");
    }
  }
  if (scene.table_plane) {
    std::ofstream plane((dir / "table_plane.txt").string());
    plane << std::setprecision(9) << (*scene.table_plane)[0] << ' ' << (*scene.table_plane)[1] << ' '
          << (*scene.table_plane)[2] << ' ' << (*scene.table_plane)[3] << '\n';
  }
  if (!scene.labels.empty()) {
    if (scene.labels.size() != scene.cloud->size()) {
      throw InputError(directory, "labels and cloud sizes differ");
    }
    std::ofstream labels((dir / "labels.txt").string());
    for (int label : scene.labels) labels << label << '\n';
    if (!labels) throw InputError((dir / "labels.txt").string(), "cannot write labels");
  }

  YAML::Emitter info;
  info << YAML::BeginMap;
  if (!scene.kind.empty()) info << YAML::Key << "kind" << YAML::Value << scene.kind;
  if (scene.up) info << YAML::Key << "up" << YAML::Value << YAML::Flow << std::vector<float>{scene.up->x(), scene.up->y(), scene.up->z()};
  if (!scene.sensor_origins.empty()) {  // the loader wants a non-empty list or none at all
    info << YAML::Key << "sensor_origins" << YAML::Value << YAML::BeginSeq;
    for (const auto& origin : scene.sensor_origins) {
      info << YAML::Flow << std::vector<float>{origin.x(), origin.y(), origin.z()};
    }
    info << YAML::EndSeq;
  }
  info << YAML::EndMap;
  std::ofstream info_file((dir / "scene_info.yaml").string());
  info_file << info.c_str() << '\n';
}

}  // namespace symmetry_segmentation
