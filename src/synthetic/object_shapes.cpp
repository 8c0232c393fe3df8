// Ground-truth whole shapes of generated objects (see the header for why).
#include "symmetry_segmentation/synthetic/object_shapes.h"

#include <fstream>

#include <pcl/io/ply_io.h>
#include <pcl/point_types.h>
#include <yaml-cpp/yaml.h>

#include "symmetry_segmentation/errors.h"

namespace symmetry_segmentation {
namespace synthetic {

std::vector<Eigen::Vector3d> surfaceSamples(const SyntheticObject& object, double spacing) {
  std::vector<Eigen::Vector3d> samples;
  const Eigen::Vector3d center = object.pose * (0.5 * (object.local_min + object.local_max));
  const double radius = 0.5 * (object.local_max - object.local_min).norm();
  if (!(radius > 0.0) || !(spacing > 0.0)) return samples;
  for (int x = -1; x <= 1; ++x) {
    for (int y = -1; y <= 1; ++y) {
      for (int z = 0; z <= 1; ++z) {
        if (x == 0 && y == 0 && z == 0) continue;
        const Eigen::Vector3d from = Eigen::Vector3d(x, y, z).normalized();
        const Eigen::Vector3d u = from.unitOrthogonal();
        const Eigen::Vector3d v = from.cross(u);
        for (double a = -radius; a <= radius; a += spacing) {
          for (double b = -radius; b <= radius; b += spacing) {
            const Ray ray{center + 2.0 * radius * from + a * u + b * v, -from};
            if (const auto hit = rayIntersect(object, ray, 0.0, 4.0 * radius)) samples.push_back(hit->point);
          }
        }
      }
    }
  }
  return samples;
}

void saveObjectShapes(const SyntheticWorld& world, const Eigen::Isometry3d& world_to_scene, const std::string& directory,
                      double spacing) {
  YAML::Emitter yaml;
  yaml << YAML::Comment("Each object's whole shape, in the cloud's frame: box axes one unit direction per row (x, y, z), "
                        "size the full lengths along them. Surface samples: objects_surface.ply.");
  yaml << YAML::BeginMap << YAML::Key << "objects" << YAML::Value << YAML::BeginSeq;
  pcl::PointCloud<pcl::PointXYZL> surface;
  for (const SyntheticObject& object : world.objects) {
    if (object.label <= 0) continue;
    const Eigen::Matrix3d axes = world_to_scene.linear() * object.pose.linear();
    const Eigen::Vector3d center = world_to_scene * (object.pose * (0.5 * (object.local_min + object.local_max)));
    const Eigen::Vector3d size = object.local_max - object.local_min;
    yaml << YAML::BeginMap << YAML::Key << "label" << YAML::Value << object.label;
    yaml << YAML::Key << "shape" << YAML::Value << toString(object.shape);
    yaml << YAML::Key << "box" << YAML::Value << YAML::BeginMap;
    yaml << YAML::Key << "center" << YAML::Value << YAML::Flow << std::vector<double>{center.x(), center.y(), center.z()};
    yaml << YAML::Key << "axes" << YAML::Value << YAML::Flow << YAML::BeginSeq;
    for (int k = 0; k < 3; ++k) yaml << YAML::Flow << std::vector<double>{axes(0, k), axes(1, k), axes(2, k)};
    yaml << YAML::EndSeq;
    yaml << YAML::Key << "size" << YAML::Value << YAML::Flow << std::vector<double>{size.x(), size.y(), size.z()};
    yaml << YAML::EndMap << YAML::EndMap;
    for (const Eigen::Vector3d& world_point : surfaceSamples(object, spacing)) {
      const Eigen::Vector3d p = world_to_scene * world_point;
      pcl::PointXYZL q;
      q.x = static_cast<float>(p.x());
      q.y = static_cast<float>(p.y());
      q.z = static_cast<float>(p.z());
      q.label = static_cast<std::uint32_t>(object.label);
      surface.push_back(q);
    }
  }
  yaml << YAML::EndSeq << YAML::EndMap;
  const std::string yaml_path = directory + "/objects.yaml";
  std::ofstream out(yaml_path);
  out << yaml.c_str() << '\n';
  if (!out) throw InputError(yaml_path, "cannot write file");
  const std::string ply_path = directory + "/objects_surface.ply";
  if (surface.empty()) return;
  surface.width = static_cast<std::uint32_t>(surface.size());
  surface.height = 1;
  if (pcl::io::savePLYFileBinary(ply_path, surface) != 0) throw InputError(ply_path, "cannot write file");
}

}  // namespace synthetic
}  // namespace symmetry_segmentation
