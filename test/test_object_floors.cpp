// The floor inside a hollow object comes back to its segment; table seen beside an object, in
// an L's inner corner, under an overhanging rim or inside a handle's loop, does not.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "symmetry_segmentation/object_bottoms.h"
#include "symmetry_segmentation/object_floors.h"
#include "symmetry_segmentation/preprocessing.h"

namespace ss = symmetry_segmentation;

namespace {

enum class Part { Table, BowlFloor, Bowl, L, Ring };

struct Fixture {
  ss::Scene scene;
  ss::PreprocessParams params;
  std::vector<Part> parts;

  void add(float x, float y, float z, const Eigen::Vector3f& normal, Part part) {
    ss::PointT p;
    p.x = x;
    p.y = y;
    p.z = z;
    p.getNormalVector3fMap() = normal;
    scene.cloud->push_back(p);
    parts.push_back(part);
  }

  // A bowl at (0, 0): wall from radius 6 cm at the table out to 8 cm at its rim (5 cm high),
  // floor 4 mm up inside radius 5.5 cm (within the 1 cm table margin). An L at (0.25, 0):
  // two 5 cm wide bars 20 cm long, its top 6 cm up. A ring of radius 1.5 cm at (-0.25, 0), a
  // handle's loop seen from above. The table everywhere else no object hides: not under the
  // bowl's base or the L, but under the bowl's overhanging rim and inside the ring.
  Fixture() {
    scene.cloud = std::make_shared<ss::Cloud>();
    const float step = 0.004f;
    const Eigen::Vector3f up = Eigen::Vector3f::UnitZ();
    auto underL = [](float x, float y) {
      return (x >= 0.25f && x <= 0.45f && y >= 0.0f && y <= 0.05f) || (x >= 0.25f && x <= 0.30f && y >= 0.0f && y <= 0.2f);
    };
    for (float x = -0.4f; x <= 0.6f; x += step) {
      for (float y = -0.3f; y <= 0.3f; y += step) {
        const float r = std::hypot(x, y);
        if (r < 0.055f) {
          add(x, y, 0.004f, up, Part::BowlFloor);
        } else if (r >= 0.06f && !underL(x, y)) {
          add(x, y, 0.0f, up, Part::Table);
        }
        if (underL(x, y)) add(x, y, 0.06f, up, Part::L);
      }
    }
    for (float z = 0.0f; z <= 0.05f; z += step) {
      const float radius = 0.06f + 0.4f * z;
      for (float a = 0.0f; a < 2.0f * static_cast<float>(M_PI); a += step / radius) {
        add(radius * std::cos(a), radius * std::sin(a), z, Eigen::Vector3f(std::cos(a), std::sin(a), -0.4f).normalized(),
            Part::Bowl);
      }
    }
    for (float z = 0.0f; z <= 0.03f; z += step) {
      for (float a = 0.0f; a < 2.0f * static_cast<float>(M_PI); a += step / 0.015f) {
        add(-0.25f + 0.015f * std::cos(a), 0.015f * std::sin(a), z + 0.02f, Eigen::Vector3f(std::cos(a), std::sin(a), 0.0f),
            Part::Ring);
      }
    }
    scene.has_normals = true;
    scene.table_plane = ss::PlaneCoefficients(0.0f, 0.0f, 1.0f, 0.0f);
    params.adaptive_table_margin = false;
    params.table_margin = 0.01f;
  }

  std::vector<int> kept(const ss::PreprocessedScene& prepared, Part part) const {
    std::vector<int> points;
    for (std::size_t i = 0; i < parts.size(); ++i) {
      if (parts[i] == part && prepared.input_to_voxel[i] >= 0) points.push_back(static_cast<int>(i));
    }
    return points;
  }
  int count(const std::vector<int>& points, Part part) const {
    return static_cast<int>(std::count_if(points.begin(), points.end(), [&](int i) { return parts[i] == part; }));
  }
};

}  // namespace

TEST(ObjectFloors, ABowlsFloorRejoinsItAndTableBesideObjectsStaysOut) {
  const Fixture fixture;
  const ss::PreprocessedScene prepared = ss::preprocess(fixture.scene, fixture.params);
  const std::vector<std::vector<int>> segments = {fixture.kept(prepared, Part::Bowl), fixture.kept(prepared, Part::L),
                                                  fixture.kept(prepared, Part::Ring)};
  for (const auto& segment : segments) ASSERT_FALSE(segment.empty());
  const int floor_points = static_cast<int>(std::count(fixture.parts.begin(), fixture.parts.end(), Part::BowlFloor));

  ss::FloorParams params;
  const auto floors = ss::enclosedFloors(fixture.scene, prepared, segments, {}, params);
  ASSERT_EQ(floors.size(), 3u);
  EXPECT_TRUE(std::is_sorted(floors[0].begin(), floors[0].end()));
  EXPECT_GE(fixture.count(floors[0], Part::BowlFloor), static_cast<int>(0.9 * floor_points));
  // The table under the rim (6 to 8 cm out) is enclosed too; the outermost cells are left out.
  EXPECT_LE(fixture.count(floors[0], Part::Table), 0.05 * floor_points);
  EXPECT_TRUE(floors[1].empty()) << floors[1].size() << " points of the L's inner corner";
  EXPECT_TRUE(floors[2].empty()) << floors[2].size() << " points inside the handle's loop";

  // Points already given back (taken) are not given twice; no table, no floors.
  const auto without_taken = ss::enclosedFloors(fixture.scene, prepared, segments, floors[0], params);
  EXPECT_TRUE(without_taken[0].empty());
  ss::PreprocessedScene no_table = prepared;
  no_table.has_table = false;
  EXPECT_TRUE(ss::enclosedFloors(fixture.scene, no_table, segments, {}, params)[0].empty());

  // object_bottoms gives them back with min_floor_area > 0, not with 0.
  ss::ObjectBottomParams bottoms;
  EXPECT_GE(fixture.count(ss::objectBottoms(fixture.scene, prepared, fixture.params.voxel_size, segments, bottoms)[0],
                          Part::BowlFloor),
            static_cast<int>(0.9 * floor_points));
  bottoms.min_floor_area = 0.0f;
  EXPECT_EQ(fixture.count(ss::objectBottoms(fixture.scene, prepared, fixture.params.voxel_size, segments, bottoms)[0],
                          Part::BowlFloor),
            0);
}

TEST(ObjectFloors, NoFloorUnderABoardHeldOverTheTable) {
  // The table seen all over (a camera sees it under a shelf from the side), and two flat tops
  // 20 x 20 cm: one 3 cm over it (a box standing on it), one 35 cm over it (a shelf). The
  // footprint of either encloses the table under it; only the standing one has a floor there.
  ss::Scene scene;
  scene.cloud = std::make_shared<ss::Cloud>();
  std::vector<int> standing, shelf;
  const auto add = [&](float x, float y, float z, std::vector<int>* part) {
    ss::PointT p;
    p.x = x;
    p.y = y;
    p.z = z;
    p.getNormalVector3fMap() = Eigen::Vector3f::UnitZ();
    if (part != nullptr) part->push_back(static_cast<int>(scene.cloud->size()));
    scene.cloud->push_back(p);
  };
  const float step = 0.005f;
  for (float x = -0.4f; x <= 0.4f; x += step) {
    for (float y = -0.2f; y <= 0.2f; y += step) add(x, y, 0.0f, nullptr);
  }
  for (float x = -0.3f; x <= -0.1f; x += step) {
    for (float y = -0.1f; y <= 0.1f; y += step) {
      add(x, y, 0.03f, &standing);
      add(x + 0.4f, y, 0.35f, &shelf);
    }
  }
  scene.has_normals = true;
  scene.table_plane = ss::PlaneCoefficients(0.0f, 0.0f, 1.0f, 0.0f);
  ss::PreprocessParams preprocessing;
  preprocessing.adaptive_table_margin = false;
  preprocessing.table_margin = 0.01f;
  const ss::PreprocessedScene prepared = ss::preprocess(scene, preprocessing);

  const auto floors = ss::enclosedFloors(scene, prepared, {standing, shelf}, {}, ss::FloorParams{});
  ASSERT_EQ(floors.size(), 2u);
  EXPECT_GT(floors[0].size(), 500u) << "the table hidden under the standing box";
  EXPECT_TRUE(floors[1].empty()) << floors[1].size() << " points of the table under the shelf";
}
