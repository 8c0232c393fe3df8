#include "symmetry_segmentation/synthetic/scene_generator.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>
#include <string>

#include "symmetry_segmentation/synthetic/room.h"

#include "symmetry_segmentation/errors.h"

namespace symmetry_segmentation {
namespace synthetic {
namespace {

// Independent random streams, so changing e.g. the number of views leaves the layout alone.
constexpr uint64_t kLayoutStream = 0;
constexpr uint64_t kCameraStream = 1;
constexpr uint64_t kFusionStream = 2;
constexpr uint64_t kRoomStream = 3;
constexpr uint64_t kPrintStream = 4;
constexpr uint64_t kFirstViewStream = 100;

void require(bool condition, const std::string& problem) {
  if (!condition) throw InputError("synthetic scene options: " + problem);
}

/// Light from above, a little in front of the table.
void shade(std::vector<RenderedView>& views) {
  const Eigen::Vector3f light = Eigen::Vector3f(0.3f, -0.4f, 1.0f).normalized();
  for (auto& view : views) {
    for (auto& point : view.points) {
      const float factor = 0.55f + 0.45f * std::max(0.0f, point.normal.dot(light));
      for (auto& c : point.color) c = static_cast<uint8_t>(std::lround(c * factor));
    }
  }
}

/// A camera looking at `focus` from `azimuth` (degrees, -90 = in front, -y) with elevation
/// and distance drawn from the options' ranges.
CameraPose cameraAt(const GeneratorOptions& options, const Eigen::Vector3d& focus, double azimuth_deg,
                    Random& random) {
  const double azimuth = azimuth_deg * M_PI / 180.0;
  const double elevation = random.uniform(options.min_elevation_deg, options.max_elevation_deg) * M_PI / 180.0;
  const double distance = random.uniform(options.min_distance, options.max_distance);
  const Eigen::Vector3d eye = focus + distance * Eigen::Vector3d(std::cos(elevation) * std::cos(azimuth),
                                                                 std::cos(elevation) * std::sin(azimuth),
                                                                 std::sin(elevation));
  return lookAt(eye, focus);
}

/// The organized frame in the camera's optical frame (x right, y down, z forward).
void fillSingleView(const RenderedView& view, const CameraPose& camera, const CameraIntrinsics& intrinsics,
                    Scene& scene) {
  const float nan = std::numeric_limits<float>::quiet_NaN();
  auto cloud = std::make_shared<Cloud>();
  cloud->width = static_cast<uint32_t>(intrinsics.width);
  cloud->height = static_cast<uint32_t>(intrinsics.height);
  cloud->is_dense = false;
  PointT empty;
  empty.x = empty.y = empty.z = nan;
  empty.normal_x = empty.normal_y = empty.normal_z = nan;
  empty.r = empty.g = empty.b = 0;
  cloud->points.assign(static_cast<std::size_t>(intrinsics.width) * intrinsics.height, empty);
  scene.labels.assign(cloud->size(), 0);
  const Eigen::Isometry3f world_to_camera = camera.camera_to_world.inverse().cast<float>();
  for (const auto& point : view.points) {
    auto& out = cloud->points[static_cast<std::size_t>(point.pixel)];
    out.getVector3fMap() = world_to_camera * point.position;
    out.r = point.color[0];
    out.g = point.color[1];
    out.b = point.color[2];
    scene.labels[static_cast<std::size_t>(point.pixel)] = point.label;
  }
  scene.cloud = cloud;
  scene.has_normals = false;
  scene.has_color = true;
  scene.sensor_origins = {Eigen::Vector3f::Zero()};
  // A camera on a robot knows gravity from tf; a fused volume's frame is arbitrary, so only the
  // single view carries its up.
  scene.up = (world_to_camera.linear() * Eigen::Vector3f::UnitZ()).normalized();
}

}  // namespace

const std::vector<std::string>& depthSensorNames() {
  static const std::vector<std::string> names = {"kinect", "realsense"};
  return names;
}

void useDepthSensor(GeneratorOptions& options, const std::string& sensor) {
  options.single_view = true;
  options.num_views = 1;
  options.build_occupancy = false;
  options.min_distance = 0.7;
  options.max_distance = 1.2;
  options.min_elevation_deg = 30.0;
  options.max_elevation_deg = 55.0;
  options.intrinsics = CameraIntrinsics{};
  options.noise = DepthNoiseModel{};
  if (sensor == "kinect") {
    options.noise.disparity_focal_baseline = 577.3 * 0.075;
    options.noise.disparity_step = 1.0 / 8.0;
    options.noise.projector_baseline = 0.075;
  } else if (sensor == "realsense") {
    // Depth registered to the 69 deg colour camera; the stereo pair itself has f ~ 385 px at
    // this resolution, 5 cm apart, and ~0.08 px disparity noise.
    options.intrinsics.fx = options.intrinsics.fy = 615.0;
    options.noise.sigma_per_square_metre = 0.08 / (385.0 * 0.05);
    options.noise.disparity_focal_baseline = 385.0 * 0.05;
    options.noise.disparity_step = 1.0 / 16.0;
    options.noise.projector_baseline = 0.05;
    options.noise.min_depth = 0.3;
    options.noise.grazing_start_deg = 65.0;
    options.noise.grazing_full_deg = 84.0;
  } else {
    std::string known;
    for (const auto& name : depthSensorNames()) known += (known.empty() ? "" : ", ") + name;
    throw InputError("unknown depth sensor '" + sensor + "' (expected one of: " + known + ")");
  }
}

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
  require(options.realism.printed_share >= 0.0 && options.realism.printed_share <= 1.0,
          "printed_share must be in 0..1");
  require(options.realism.max_books >= 0 && options.realism.max_books <= 6, "max_books must be in 0..6");
  require(!options.single_view || options.num_views == 1, "a single view has one camera");
}

std::vector<CameraPose> cameraArc(const GeneratorOptions& options, const Eigen::Vector3d& focus, Random& random) {
  std::vector<CameraPose> cameras;
  for (int i = 0; i < options.num_views; ++i) {
    const double fraction = options.num_views == 1 ? 0.5 : static_cast<double>(i) / (options.num_views - 1);
    cameras.push_back(cameraAt(options, focus, -90.0 + options.arc_degrees * (fraction - 0.5), random));
  }
  return cameras;
}

GeneratedScene generate(const GeneratorOptions& options) {
  validate(options);
  GeneratedScene result;
  Random layout_random(deriveSeed(options.seed, kLayoutStream));
  const TableSize table;
  result.layout = layoutScene(options.kind, layout_random, table, options.realism);
  if (options.realism.room) {
    Random room_random(deriveSeed(options.seed, kRoomStream));
    addRoom(result.layout.world, table, room_random);
  }
  if (options.realism.printed_share > 0.0) {
    Random print_random(deriveSeed(options.seed, kPrintStream));
    addPrints(result.layout.world, options.realism.printed_share, print_random);
  }
  Random camera_random(deriveSeed(options.seed, kCameraStream));
  if (options.single_view) {
    result.cameras = {cameraAt(options, result.layout.focus, -90.0 + camera_random.uniform(-25.0, 25.0), camera_random)};
  } else {
    result.cameras = cameraArc(options, result.layout.focus, camera_random);
  }

  std::vector<RenderedView> views;
  for (std::size_t i = 0; i < result.cameras.size(); ++i) {
    Random view_random(deriveSeed(options.seed, kFirstViewStream + i));
    views.push_back(renderView(result.layout.world, result.cameras[i], options.intrinsics, options.noise, view_random));
  }

  if (options.realism.shading) shade(views);

  Scene& scene = result.scene;
  scene.kind = toString(options.kind);
  scene.name = scene.kind + "_seed" + std::to_string(options.seed);
  if (options.single_view) {
    fillSingleView(views.front(), result.cameras.front(), options.intrinsics, scene);
    result.world_to_scene = result.cameras.front().camera_to_world.inverse();
    return result;
  }

  FusionOptions fusion;
  fusion.voxel_size = options.voxel_size;
  Random fusion_random(deriveSeed(options.seed, kFusionStream));
  FusedCloud fused = fuseViews(views, fusion, fusion_random);

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
