// Reading PLY / PCD clouds with validation, so bad files give one clear line, never a crash.
#include <algorithm>
#include <cstdint>
#include <string>

#include <boost/filesystem.hpp>
#include <pcl/PCLPointCloud2.h>
#include <pcl/console/print.h>
#include <pcl/conversions.h>
#include <pcl/io/pcd_io.h>
#include <pcl/io/ply_io.h>

#include "symmetry_segmentation/cloud_header_check.h"
#include "symmetry_segmentation/point_validity.h"
#include "symmetry_segmentation/scene_io.h"

namespace symmetry_segmentation {
namespace {

bool hasField(const pcl::PCLPointCloud2& cloud, const std::string& name) {
  for (const auto& field : cloud.fields) {
    if (field.name == name) return true;
  }
  return false;
}

std::string lowerExtension(const std::string& path) {
  std::string ext = boost::filesystem::path(path).extension().string();
  for (auto& c : ext) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return ext;
}

// Both readers run after checkPcdFile / checkPlyFile: PCL sizes its buffers from the header,
// which by then is bounded by the bytes the file really holds.
void readPcd(const std::string& path, pcl::PCLPointCloud2& cloud, Eigen::Vector4f& origin,
             Eigen::Quaternionf& orientation) {
  pcl::PCDReader reader;
  int version = 0;
  if (reader.read(path, cloud, origin, orientation, version) < 0) {
    throw InputError(path, "corrupt or truncated PCD data");
  }
}

void readPly(const std::string& path, pcl::PCLPointCloud2& cloud, Eigen::Vector4f& origin,
             Eigen::Quaternionf& orientation) {
  pcl::PLYReader reader;
  int version = 0;
  if (reader.read(path, cloud, origin, orientation, version) < 0) {
    throw InputError(path, "corrupt or truncated PLY data");
  }
}

// PCL writes a camera element into every PLY it saves, at the origin with identity orientation
// when the cloud had no real viewpoint; only a camera with another pose says where a sensor was.
bool isDefaultPose(const Eigen::Vector4f& origin, const Eigen::Quaternionf& orientation) {
  return origin.head<3>().isZero(0.0f) && orientation.coeffs() == Eigen::Quaternionf::Identity().coeffs();
}

// What PCL returned must match what the checked header declared (no short reads).
void checkReadSize(const std::string& path, const pcl::PCLPointCloud2& raw, std::uint64_t declared) {
  const std::uint64_t count = static_cast<std::uint64_t>(raw.width) * raw.height;
  if (count != declared) {
    throw InputError(path, "corrupt cloud data (read " + std::to_string(count) + " of " +
                               std::to_string(declared) + " declared points)");
  }
  // count <= kMaxCloudPoints and point_step < 2^32, so the product cannot wrap.
  if (raw.data.size() < count * raw.point_step) throw InputError(path, "truncated point data");
}

// PCL warns on stderr about every field a file lacks (no normals, unhandled camera
// properties); those are expected here and drown the one-line errors users need to see.
class QuietPclWarnings {
 public:
  QuietPclWarnings() : saved_(pcl::console::getVerbosityLevel()) {
    pcl::console::setVerbosityLevel(pcl::console::L_ERROR);
  }
  ~QuietPclWarnings() { pcl::console::setVerbosityLevel(saved_); }

 private:
  pcl::console::VERBOSITY_LEVEL saved_;
};

}  // namespace

void loadCloudFile(const std::string& path, Scene& scene) {
  checkReadableFile(path);
  boost::system::error_code ec;
  if (boost::filesystem::file_size(path, ec) == 0) throw InputError(path, "file is empty");
  const QuietPclWarnings quiet;
  const std::string ext = lowerExtension(path);
  pcl::PCLPointCloud2 raw;
  Eigen::Vector4f origin = Eigen::Vector4f::Zero();
  Eigen::Quaternionf orientation = Eigen::Quaternionf::Identity();
  CloudFileSummary summary;
  try {
    if (ext == ".pcd") {
      summary = checkPcdFile(path);
      readPcd(path, raw, origin, orientation);
    } else if (ext == ".ply") {
      summary = checkPlyFile(path);
      readPly(path, raw, origin, orientation);
    } else {
      throw InputError(path, "unsupported cloud format '" + ext + "' (expected .ply or .pcd)");
    }
  } catch (const InputError&) {
    throw;
  } catch (const std::exception& e) {
    throw InputError(path, std::string("cannot parse cloud: ") + e.what());
  }

  checkReadSize(path, raw, summary.points);
  if (!hasField(raw, "x") || !hasField(raw, "y") || !hasField(raw, "z")) {
    throw InputError(path, "cloud lacks x, y, z fields");
  }

  auto cloud = std::make_shared<Cloud>();
  pcl::fromPCLPointCloud2(raw, *cloud);
  scene.has_normals = hasField(raw, "normal_x") && hasField(raw, "normal_y") && hasField(raw, "normal_z");
  scene.has_color = hasField(raw, "rgb") || hasField(raw, "rgba");
  if (hasField(raw, "label")) {
    pcl::PointCloud<pcl::Label> labels;
    pcl::fromPCLPointCloud2(raw, labels);
    scene.file_labels.reserve(labels.size());
    for (const pcl::Label& point : labels) scene.file_labels.push_back(point.label);
  }

  if (std::none_of(cloud->points.begin(), cloud->points.end(), isUsablePoint)) {
    throw InputError(path, "cloud has no finite points within 100 km (all NaN, infinite or farther)");
  }

  const bool trusted_origin = ext == ".pcd" || (summary.has_camera && !isDefaultPose(origin, orientation));
  if (trusted_origin && origin.head<3>().allFinite()) {
    scene.sensor_origins.push_back(origin.head<3>());
  }
  cloud->sensor_origin_ = origin;
  cloud->sensor_orientation_ = orientation;
  scene.cloud = cloud;
  scene.cloud_path = path;
}

}  // namespace symmetry_segmentation
