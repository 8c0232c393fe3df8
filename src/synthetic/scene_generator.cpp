#include "symmetry_segmentation/synthetic/scene_generator.h"

#include <cmath>
#include <string>

#include "symmetry_segmentation/errors.h"

namespace symmetry_segmentation {
namespace synthetic {
namespace {

// Independent random streams, so changing e.g. the number of views leaves the layout alone.
constexpr uint64_t kLayoutStream = 0;
constexpr uint64_t kCameraStream = 1;
constexpr uint64_t kFusionStream = 2;
constexpr uint64_t kFirstViewStream = 100;

void require(bool condition, const std::string& problem) {
  if (!condition) throw InputError("synthetic scene options: " + problem);
}

}  // namespace

void validate(const GeneratorOptions& options) {
  require(options.num_views >= 1 && options.num_views <= 16, "num_views must be in 1..16");
  require(options.arc_degrees >= 0.0 && options.arc_degrees <= 180.0, "arc_degrees must be in 0..180");
  require(options.min_distance >= 0.5 && options.min_distance <= options.max_distance && options.max_distance <= 3.0,
          "camera distances must satisfy 0.5 <= min_distance <= max_distance <= 3");
  require(options.min_elevation_deg >= 5.0 && options.min_elevation_deg <= options.max_elevation_deg &&
              options.max_elevation_deg <= 85.0,
          "elevations must satisfy 5 <= min_elevation_deg <= max_elevation_deg <= 85");
  require(options.voxel_size >= 0.0005 && options.voxel_size <= 0.05, "voxel_size must be in 0.0005..0.05 m");
  require(options.octomap_resolution >= 0.002 && options.octomap_resolution <= 0.2,
          "octomap_resolution must be in 0.002..0.2 m");
  require(options.intrinsics.width > 0 && options.intrinsics.height > 0 && options.intrinsics.width <= 4096 &&
              options.intrinsics.height <= 4096,
          "image size must be in 1..4096 pixels");
  require(options.intrinsics.fx > 0.0 && options.intrinsics.fy > 0.0, "focal lengths must be positive");
  require(options.noise.sigma_per_square_metre >= 0.0, "depth noise must not be negative");
}

std::vector<CameraPose> cameraArc(const GeneratorOptions& options, const Eigen::Vector3d& focus, Random& random) {
  std::vector<CameraPose> cameras;
  for (int i = 0; i < options.num_views; ++i) {
    const double fraction = options.num_views == 1 ? 0.5 : static_cast<double>(i) / (options.num_views - 1);
    const double azimuth = (-90.0 + options.arc_degrees * (fraction - 0.5)) * M_PI / 180.0;
    const double elevation = random.uniform(options.min_elevation_deg, options.max_elevation_deg) * M_PI / 180.0;
    const double distance = random.uniform(options.min_distance, options.max_distance);
    const Eigen::Vector3d eye =
        focus + distance * Eigen::Vector3d(std::cos(elevation) * std::cos(azimuth),
                                           std::cos(elevation) * std::sin(azimuth), std::sin(elevation));
    cameras.push_back(lookAt(eye, focus));
  }
  return cameras;
}

GeneratedScene generate(const GeneratorOptions& options) {
  validate(options);
  GeneratedScene result;
  Random layout_random(deriveSeed(options.seed, kLayoutStream));
  result.layout = layoutScene(options.kind, layout_random);
  Random camera_random(deriveSeed(options.seed, kCameraStream));
  result.cameras = cameraArc(options, result.layout.focus, camera_random);

  std::vector<RenderedView> views;
  for (std::size_t i = 0; i < result.cameras.size(); ++i) {
    Random view_random(deriveSeed(options.seed, kFirstViewStream + i));
    views.push_back(renderView(result.layout.world, result.cameras[i], options.intrinsics, options.noise, view_random));
  }

  FusionOptions fusion;
  fusion.voxel_size = options.voxel_size;
  Random fusion_random(deriveSeed(options.seed, kFusionStream));
  FusedCloud fused = fuseViews(views, fusion, fusion_random);

  Scene& scene = result.scene;
  scene.kind = toString(options.kind);
  scene.name = scene.kind + "_seed" + std::to_string(options.seed);
  scene.cloud = fused.cloud;
  scene.labels = std::move(fused.labels);
  scene.has_normals = true;
  scene.has_color = true;
  for (const auto& view : views) scene.sensor_origins.push_back(view.origin.cast<float>());
  scene.table_plane = PlaneCoefficients(0.0f, 0.0f, 1.0f, 0.0f);
  if (options.build_occupancy) {
    scene.occupancy = buildOccupancy(views, options.octomap_resolution, options.octomap_max_range);
  }
  return result;
}

Scene generateScene(const GeneratorOptions& options) { return generate(options).scene; }

}  // namespace synthetic
}  // namespace symmetry_segmentation
