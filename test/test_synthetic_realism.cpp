// What the realistic generator adds (room, prints, books, more shapes) and the single-view
// depth sensors: each feature does what it says and leaves the rest of the scene alone.

#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <set>

#include <Eigen/Geometry>
#include <boost/filesystem.hpp>

#include "symmetry_segmentation/errors.h"
#include "symmetry_segmentation/scene_io.h"
#include "symmetry_segmentation/synthetic/object_library.h"
#include "symmetry_segmentation/synthetic/room.h"
#include "symmetry_segmentation/synthetic/scene_generator.h"
#include "test_support.h"

namespace ss = symmetry_segmentation;
using namespace symmetry_segmentation::synthetic;

namespace {

GeneratorOptions fusedOptions(SceneKind kind, uint32_t seed, const RealismOptions& realism) {
  GeneratorOptions options;
  options.kind = kind;
  options.seed = seed;
  options.num_views = 2;
  options.build_occupancy = false;
  options.realism = realism;
  return options;
}

GeneratorOptions singleViewOptions(SceneKind kind, uint32_t seed, const std::string& sensor) {
  GeneratorOptions options;
  options.kind = kind;
  options.seed = seed;
  useDepthSensor(options, sensor);
  return options;
}

int finitePoints(const ss::Cloud& cloud) {
  int count = 0;
  for (const auto& p : cloud.points) count += std::isfinite(p.z) ? 1 : 0;
  return count;
}

}  // namespace

TEST(SyntheticRealism, RoomIsBackgroundAndLeavesTheLayoutAlone) {
  RealismOptions room_only;
  room_only.room = true;
  const GeneratedScene plain = generate(fusedOptions(SceneKind::Isolated, 7, RealismOptions{}));
  const GeneratedScene room = generate(fusedOptions(SceneKind::Isolated, 7, room_only));
  ASSERT_EQ(plain.layout.world.objects.size(), room.layout.world.objects.size());
  for (std::size_t i = 0; i < plain.layout.world.objects.size(); ++i) {
    EXPECT_TRUE(plain.layout.world.objects[i].pose.isApprox(room.layout.world.objects[i].pose)) << i;
  }
  EXPECT_TRUE(plain.layout.world.background.empty());
  EXPECT_GE(room.layout.world.background.size(), 7u) << "wall, floor, four legs, floor clutter";

  // The room is seen, and only as label 0: the wall above the table behind it, the floor below.
  int wall = 0, below_table = 0;
  const ss::Scene& scene = room.scene;
  for (std::size_t i = 0; i < scene.size(); ++i) {
    const auto& p = scene.cloud->points[i];
    if (p.y > 0.4f && p.z > 0.15f) {
      ++wall;
      EXPECT_EQ(scene.labels[i], 0);
    }
    if (p.z < -0.1f) {
      ++below_table;
      EXPECT_EQ(scene.labels[i], 0);
    }
  }
  EXPECT_GT(wall, 2000);
  EXPECT_GT(below_table, 100);
  EXPECT_GT(scene.size(), plain.scene.size());
}

TEST(SyntheticRealism, NothingOfTheRoomPassesThroughTheTableTop) {
  // A chair's back rises over the table top beside its end; standing partly inside the table's
  // footprint it came up through the top as a slab no real room has. Nothing of the room may
  // share volume with the top; the shelf above it and the legs and clutter below it do not.
  const TableSize table;
  const Eigen::AlignedBox3d top(Eigen::Vector3d(-table.size_x / 2, -table.size_y / 2, -table.thickness),
                                Eigen::Vector3d(table.size_x / 2, table.size_y / 2, 0.0));
  int rising_over_the_top = 0;
  for (uint64_t seed = 1; seed <= 300; ++seed) {
    SyntheticWorld world;
    Random random(seed);
    addRoom(world, table, random);
    for (const SyntheticObject& piece : world.background) {
      Eigen::AlignedBox3d bounds;
      for (int corner = 0; corner < 8; ++corner) {
        const Eigen::Vector3d local((corner & 1) ? piece.local_max.x() : piece.local_min.x(),
                                    (corner & 2) ? piece.local_max.y() : piece.local_min.y(),
                                    (corner & 4) ? piece.local_max.z() : piece.local_min.z());
        bounds.extend(piece.pose * local);
      }
      if (bounds.max().z() > 0.0 && bounds.min().z() < 0.0) ++rising_over_the_top;
      const Eigen::AlignedBox3d shared = bounds.intersection(top);
      const bool overlaps = !shared.isEmpty() && (shared.max() - shared.min()).minCoeff() > 1e-9;
      EXPECT_FALSE(overlaps) << "seed " << seed << ": a piece of the room from " << bounds.min().transpose()
                             << " to " << bounds.max().transpose() << " passes through the table top";
    }
  }
  // Chair backs and the wall do rise past the top's height: the test looks at them.
  EXPECT_GT(rising_over_the_top, 300);
}

TEST(SyntheticRealism, PrintsGiveObjectsSeveralColoursFixedToTheObject) {
  SyntheticWorld world;
  world.objects.push_back(makeBox(0.2, 0.1, 0.2));
  world.objects.push_back(makeCylinder(0.05, 0.2));
  world.objects[1].pose = uprightPose(0.4, 0.0, 0.0, 0.0);
  Random random(3);
  addPrints(world, 1.0, random);
  for (const auto& object : world.objects) {
    ASSERT_TRUE(object.print.enabled);
    std::set<Rgb> colors;
    // Points on the object's front face (y = min) across its width and height.
    for (double u = 0.05; u < 0.95; u += 0.05) {
      for (double v = 0.05; v < 0.95; v += 0.05) {
        const Eigen::Vector3d local(object.local_min.x() + u * (object.local_max.x() - object.local_min.x()),
                                    object.local_min.y(), v * object.height());
        colors.insert(surfaceColor(object, object.pose * local));
      }
    }
    EXPECT_GE(colors.size(), 3u) << toString(object.shape);
    EXPECT_TRUE(colors.count(object.color)) << "the base colour shows between the inks";
    // The print moves with the object.
    SyntheticObject moved = object;
    moved.pose = uprightPose(-0.3, 0.2, 0.0, 0.7) * object.pose;
    const Eigen::Vector3d local(0.01, object.local_min.y(), 0.05);
    EXPECT_EQ(surfaceColor(object, object.pose * local), surfaceColor(moved, moved.pose * local));
  }
  Random none(3);
  addPrints(world, 0.0, none);
  for (const auto& object : world.objects) {
    EXPECT_EQ(surfaceColor(object, object.pose * Eigen::Vector3d(0.01, 0.0, 0.05)), object.color);
  }
}

TEST(SyntheticRealism, BooksLieFlatAndMoreShapesAreDrawn) {
  RealismOptions realism;
  realism.max_books = 3;
  realism.more_shapes = true;
  int books = 0;
  std::set<ObjectShape> shapes;
  for (uint32_t seed = 1; seed <= 8; ++seed) {
    Random random(seed);
    const SceneLayout layout = layoutScene(SceneKind::Isolated, random, TableSize{}, realism);
    const auto& objects = layout.world.objects;
    for (std::size_t i = 0; i < objects.size(); ++i) {
      shapes.insert(objects[i].shape);
      EXPECT_EQ(objects[i].label, static_cast<int>(i) + 1);
      if (objects[i].shape == ObjectShape::Book) {
        ++books;
        EXPECT_LT(objects[i].height(), 0.05);
        EXPECT_GT(objects[i].local_max.x() - objects[i].local_min.x(), 0.13);
      }
      for (std::size_t j = i + 1; j < objects.size(); ++j) {
        EXPECT_GE(separation(objects[i].worldFootprint(), objects[j].worldFootprint()), -1e-6) << seed;
      }
    }
  }
  EXPECT_GE(books, 4) << "0-3 books per scene over 8 scenes";
  EXPECT_TRUE(shapes.count(ObjectShape::Ball) || shapes.count(ObjectShape::Pot));

  // Off, the layout is the fixed set's.
  Random a(5), b(5);
  const SceneLayout plain = layoutScene(SceneKind::Clutter, a);
  const SceneLayout explicit_plain = layoutScene(SceneKind::Clutter, b, TableSize{}, RealismOptions{});
  ASSERT_EQ(plain.world.objects.size(), explicit_plain.world.objects.size());
  for (std::size_t i = 0; i < plain.world.objects.size(); ++i) {
    EXPECT_TRUE(plain.world.objects[i].pose.isApprox(explicit_plain.world.objects[i].pose));
    EXPECT_NE(plain.world.objects[i].shape, ObjectShape::Book);
  }
}

TEST(SyntheticRealism, SingleKinectViewIsAnOrganizedCameraFrameWithQuantisedDepth) {
  const GeneratorOptions options = singleViewOptions(SceneKind::Clutter, 4, "kinect");
  const GeneratedScene generated = generate(options);
  const ss::Scene& scene = generated.scene;
  ASSERT_TRUE(scene.cloud);
  EXPECT_EQ(scene.cloud->width, 640u);
  EXPECT_EQ(scene.cloud->height, 480u);
  EXPECT_FALSE(scene.has_normals);
  EXPECT_FALSE(scene.occupancy);
  EXPECT_FALSE(scene.table_plane);
  ASSERT_EQ(scene.sensor_origins.size(), 1u);
  EXPECT_TRUE(scene.sensor_origins[0].isZero());
  ASSERT_EQ(scene.labels.size(), scene.size());

  const double fb = options.noise.disparity_focal_baseline;
  const int finite = finitePoints(*scene.cloud);
  EXPECT_GT(finite, 150000);
  EXPECT_LT(finite, 640 * 480);
  std::set<int> labels;
  for (std::size_t i = 0; i < scene.size(); ++i) {
    const auto& p = scene.cloud->points[i];
    if (!std::isfinite(p.z)) {
      EXPECT_EQ(scene.labels[i], 0);
      continue;
    }
    labels.insert(scene.labels[i]);
    // Camera frame: in front of the camera, on a disparity step of 1/8 pixel. The PCD stores
    // floats, so allow their rounding.
    ASSERT_GT(p.z, 0.3f);
    const double steps = fb / p.z / options.noise.disparity_step;
    ASSERT_NEAR(steps, std::round(steps), 2e-3 * steps) << p.z;
  }
  EXPECT_GE(labels.size(), generated.layout.world.objects.size() * 3 / 4) << "most objects are in view";

  // Projector shadows: the same frame with the projector on the camera sees fewer pixels.
  GeneratorOptions no_shadow = options;
  no_shadow.noise.projector_baseline = 0.0;
  EXPECT_GT(finitePoints(*generate(no_shadow).scene.cloud), finite + 1000);
}

TEST(SyntheticRealism, SingleViewSavesAsOrganizedPcdAndLoadsBack) {
  GeneratorOptions options = singleViewOptions(SceneKind::Stacked, 2, "realsense");
  options.realism = RealismOptions::realistic();
  const ss::Scene scene = generateScene(options);
  const std::string dir = test_support::makeTempDir("single_view_scene") + "/scene";
  ss::saveScene(scene, dir);
  EXPECT_TRUE(boost::filesystem::exists(dir + "/cloud.pcd"));
  EXPECT_FALSE(boost::filesystem::exists(dir + "/cloud.ply"));
  EXPECT_FALSE(boost::filesystem::exists(dir + "/occupancy.bt"));
  EXPECT_FALSE(boost::filesystem::exists(dir + "/table_plane.txt"));
  const ss::Scene loaded = ss::loadScene(dir);
  EXPECT_EQ(loaded.cloud->width, 640u);
  EXPECT_EQ(loaded.cloud->height, 480u);
  EXPECT_FALSE(loaded.has_normals);
  EXPECT_TRUE(loaded.has_color);
  EXPECT_EQ(loaded.labels, scene.labels);
  EXPECT_EQ(loaded.kind, "stacked");
  // Gravity in the optical frame (x right, y down, z forward) of a camera looking down at the
  // table from 30-55 deg elevation: up is -y tilted towards the camera, and it is saved.
  ASSERT_TRUE(scene.up.has_value());
  const double elevation_deg = std::asin(-scene.up->z()) * 180.0 / M_PI;
  EXPECT_GE(elevation_deg, 30.0 - 1e-3);
  EXPECT_LE(elevation_deg, 55.0 + 1e-3);
  EXPECT_NEAR(scene.up->x(), 0.0, 1e-4);  // no roll
  EXPECT_LT(scene.up->y(), 0.0);
  ASSERT_TRUE(loaded.up.has_value());
  EXPECT_TRUE(loaded.up->isApprox(*scene.up, 1e-5f));
  for (std::size_t i = 0; i < scene.size(); i += 97) {
    const auto& a = scene.cloud->points[i];
    const auto& b = loaded.cloud->points[i];
    ASSERT_EQ(std::isfinite(a.z), std::isfinite(b.z)) << i;
    if (std::isfinite(a.z)) {
      EXPECT_EQ(a.getVector3fMap(), b.getVector3fMap());
      EXPECT_EQ(a.rgba, b.rgba);
    }
  }
  // Saving a fused scene into the same directory replaces the organized cloud.
  ss::saveScene(generateScene(fusedOptions(SceneKind::Stacked, 2, RealismOptions{})), dir);
  EXPECT_FALSE(boost::filesystem::exists(dir + "/cloud.pcd"));
  EXPECT_FALSE(ss::loadScene(dir).up.has_value()) << "a fused volume's frame is arbitrary";
  EXPECT_FALSE(ss::loadScene(dir).cloud->isOrganized());
}

TEST(SyntheticRealism, UnknownSensorAndBadRealismAreRejected) {
  GeneratorOptions options;
  EXPECT_THROW(useDepthSensor(options, "lidar"), ss::InputError);
  options.realism.printed_share = 1.5;
  EXPECT_THROW(validate(options), ss::InputError);
  options.realism.printed_share = 0.5;
  options.realism.max_books = -1;
  EXPECT_THROW(validate(options), ss::InputError);
  GeneratorOptions single;
  useDepthSensor(single, "kinect");
  single.num_views = 3;
  EXPECT_THROW(validate(single), ss::InputError);
}
