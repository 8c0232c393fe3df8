// Reading PLY / PCD clouds with validation, so bad files give one clear line, never a crash.
#include <cmath>
#include <fstream>
#include <string>

#include <boost/filesystem.hpp>
#include <pcl/PCLPointCloud2.h>
#include <pcl/console/print.h>
#include <pcl/conversions.h>
#include <pcl/io/pcd_io.h>
#include <pcl/io/ply_io.h>

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

// PCL fills the origin with zeros when a PLY has no camera element: only trust it when present.
bool plyHasCameraElement(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::string line;
  for (int i = 0; i < 200 && std::getline(in, line); ++i) {
    if (line.rfind("element camera", 0) == 0) return true;
    if (line.rfind("end_header", 0) == 0) break;
  }
  return false;
}

void checkReadableFile(const std::string& path) {
  namespace fs = boost::filesystem;
  boost::system::error_code ec;
  if (!fs::exists(path, ec)) throw InputError(path, "no such file");
  if (fs::is_directory(path, ec)) throw InputError(path, "is a directory, expected a file");
  std::ifstream probe(path, std::ios::binary);
  if (!probe) throw InputError(path, "cannot open file for reading");
  if (fs::file_size(path, ec) == 0) throw InputError(path, "file is empty");
}

// PCL's readers trust header sizes; check them against the file so truncated data is an error.
void checkPcdDataSize(const std::string& path, const pcl::PCLPointCloud2& header_only,
                      int data_type, unsigned int data_offset) {
  if (data_type != 1) return;  // ASCII and compressed data are checked by the reader itself
  const auto file_size = boost::filesystem::file_size(path);
  const std::uint64_t needed = static_cast<std::uint64_t>(header_only.width) * header_only.height *
                               header_only.point_step;
  if (data_offset + needed > file_size) {
    throw InputError(path, "truncated binary PCD data (" + std::to_string(file_size - data_offset) +
                               " bytes for " + std::to_string(needed) + " expected)");
  }
}

void readPcd(const std::string& path, pcl::PCLPointCloud2& cloud, Eigen::Vector4f& origin,
             Eigen::Quaternionf& orientation) {
  pcl::PCDReader reader;
  int version = 0, data_type = 0;
  unsigned int data_offset = 0;
  pcl::PCLPointCloud2 header;
  if (reader.readHeader(path, header, origin, orientation, version, data_type, data_offset) < 0) {
    throw InputError(path, "not a valid PCD file (unreadable header)");
  }
  checkPcdDataSize(path, header, data_type, data_offset);
  if (reader.read(path, cloud, origin, orientation, version) < 0) {
    throw InputError(path, "corrupt or truncated PCD data");
  }
}

void readPly(const std::string& path, pcl::PCLPointCloud2& cloud, Eigen::Vector4f& origin,
             Eigen::Quaternionf& orientation) {
  {
    std::ifstream in(path, std::ios::binary);
    std::string magic;
    std::getline(in, magic);
    if (magic.rfind("ply", 0) != 0) throw InputError(path, "not a PLY file (missing 'ply' magic)");
  }
  pcl::PLYReader reader;
  int version = 0;
  if (reader.read(path, cloud, origin, orientation, version) < 0) {
    throw InputError(path, "corrupt or truncated PLY data");
  }
  const std::uint64_t expected = static_cast<std::uint64_t>(cloud.width) * cloud.height;
  if (cloud.data.size() < expected * cloud.point_step) {
    throw InputError(path, "truncated PLY data");
  }
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
  const QuietPclWarnings quiet;
  const std::string ext = lowerExtension(path);
  pcl::PCLPointCloud2 raw;
  Eigen::Vector4f origin = Eigen::Vector4f::Zero();
  Eigen::Quaternionf orientation = Eigen::Quaternionf::Identity();
  try {
    if (ext == ".pcd") {
      readPcd(path, raw, origin, orientation);
    } else if (ext == ".ply") {
      readPly(path, raw, origin, orientation);
    } else {
      throw InputError(path, "unsupported cloud format '" + ext + "' (expected .ply or .pcd)");
    }
  } catch (const InputError&) {
    throw;
  } catch (const std::exception& e) {
    throw InputError(path, std::string("cannot parse cloud: ") + e.what());
  }

  const std::uint64_t count = static_cast<std::uint64_t>(raw.width) * raw.height;
  if (count == 0) throw InputError(path, "cloud has zero points");
  if (!hasField(raw, "x") || !hasField(raw, "y") || !hasField(raw, "z")) {
    throw InputError(path, "cloud lacks x, y, z fields");
  }
  if (raw.data.size() < count * raw.point_step) throw InputError(path, "truncated point data");

  auto cloud = std::make_shared<Cloud>();
  pcl::fromPCLPointCloud2(raw, *cloud);
  scene.has_normals = hasField(raw, "normal_x") && hasField(raw, "normal_y") && hasField(raw, "normal_z");
  scene.has_color = hasField(raw, "rgb") || hasField(raw, "rgba");

  std::size_t finite = 0;
  for (const auto& p : cloud->points) {
    if (std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z)) ++finite;
  }
  if (finite == 0) throw InputError(path, "cloud has no finite points (all NaN or infinite)");

  const bool trusted_origin = ext == ".pcd" || plyHasCameraElement(path);
  if (trusted_origin && origin.head<3>().allFinite()) {
    scene.sensor_origins.push_back(origin.head<3>());
  }
  cloud->sensor_origin_ = origin;
  cloud->sensor_orientation_ = orientation;
  scene.cloud = cloud;
  scene.cloud_path = path;
}

}  // namespace symmetry_segmentation
