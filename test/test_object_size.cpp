// Stage object_size: walls and table remnants are dropped, objects (with a few stray points) stay.
#include <gtest/gtest.h>

#include <numeric>

#include "symmetry_segmentation/symmetry/object_size.h"
#include "symmetry_segmentation/symmetry/pipeline_state.h"
#include "test_clouds.h"

namespace ss = symmetry_segmentation;

namespace {

std::vector<int> allOf(const ss::Cloud& cloud) {
  std::vector<int> indices(cloud.size());
  std::iota(indices.begin(), indices.end(), 0);
  return indices;
}

ss::PointT at(float x, float y, float z) {
  ss::PointT p;
  p.x = x; p.y = y; p.z = z;
  return p;
}

}  // namespace

TEST(ObjectSize, ExtentsFollowTheTableAndIgnoreStrayPoints) {
  auto box = std::make_shared<ss::Cloud>();
  test_clouds::addBox(*box, {0.0f, 0.0f, 0.0f}, {0.2f, 0.1f, 0.3f}, 0.01f);
  const Eigen::Vector3f up = Eigen::Vector3f::UnitZ();
  const Eigen::Vector3f extents = ss::segmentExtents(*box, allOf(*box), up);
  EXPECT_NEAR(extents[0], 0.3f, 0.03f) << "the height";
  EXPECT_NEAR(extents[1], 0.2f, 0.03f);
  EXPECT_NEAR(extents[2], 0.1f, 0.03f);

  const ss::ObjectSizeParams params;
  EXPECT_TRUE(ss::hasObjectSize(box, allOf(*box), up, params, 0.015f));
  // Three points of the background a metre away do not make it large.
  for (int k = 0; k < 3; ++k) box->push_back(at(1.0f + 0.01f * k, 0.5f, 0.1f));
  EXPECT_TRUE(ss::hasObjectSize(box, allOf(*box), up, params, 0.015f));
}

TEST(ObjectSize, WallsAndTableRemnantsAreNoObjects) {
  const Eigen::Vector3f up = Eigen::Vector3f::UnitZ();
  const ss::ObjectSizeParams params;
  // A strip of wall over the table's back edge, 0.4 m high and 0.8 m wide.
  auto wall = std::make_shared<ss::Cloud>();
  for (float x = 0.0f; x <= 0.8f; x += 0.01f) {
    for (float z = 0.01f; z <= 0.4f; z += 0.01f) wall->push_back(at(x, 0.5f, z));
  }
  EXPECT_FALSE(ss::hasObjectSize(wall, allOf(*wall), up, params, 0.015f));
  // A flat remnant of the table 0.45 m long: under max_extent, but one plane wider than 0.4 m.
  auto remnant = std::make_shared<ss::Cloud>();
  for (float x = 0.0f; x <= 0.45f; x += 0.01f) {
    for (float y = 0.0f; y <= 0.15f; y += 0.01f) remnant->push_back(at(x, y, 0.012f));
  }
  EXPECT_LT(ss::segmentExtents(*remnant, allOf(*remnant), up)[0], params.max_extent);
  EXPECT_FALSE(ss::hasObjectSize(remnant, allOf(*remnant), up, params, 0.015f));
  // A box of the same footprint is not mostly one plane: it stays.
  auto box = std::make_shared<ss::Cloud>();
  test_clouds::addBox(*box, {0.0f, 0.0f, 0.0f}, {0.45f, 0.15f, 0.1f}, 0.01f);
  EXPECT_TRUE(ss::hasObjectSize(box, allOf(*box), up, params, 0.015f));
  // Switched off, anything goes.
  ss::ObjectSizeParams off;
  off.max_extent = 0.0f;
  off.max_plane_extent = 0.0f;
  EXPECT_TRUE(ss::hasObjectSize(wall, allOf(*wall), up, off, 0.015f));
}

TEST(ObjectSize, ScrapsOfTheTablesNoiseAreNoObjectsThinLyingOnesAre) {
  // Table plane z = 0, given with a non-unit normal (heights still in metres).
  const ss::PlaneCoefficients table(0.0f, 0.0f, 2.0f, 0.0f);
  // A patch of the table's noise 0.5-1.2 cm over it, with a few stray points up to 5 cm.
  auto scene = std::make_shared<ss::Cloud>();
  for (float x = 0.0f; x <= 0.1f; x += 0.01f) {
    for (float y = 0.0f; y <= 0.1f; y += 0.01f) scene->push_back(at(x, y, 0.005f + 0.07f * x));
  }
  for (int k = 0; k < 3; ++k) scene->push_back(at(0.05f, 0.05f, 0.03f + 0.01f * k));
  std::vector<int> scrap = allOf(*scene);
  EXPECT_LT(ss::topHeight(*scene, scrap, table), 0.015f);
  // A book lying flat, 2.5 cm thick.
  const std::size_t book_start = scene->size();
  test_clouds::addBox(*scene, {0.4f, 0.0f, 0.0f}, {0.2f, 0.15f, 0.025f}, 0.01f);
  std::vector<int> book(scene->size() - book_start);
  std::iota(book.begin(), book.end(), static_cast<int>(book_start));
  EXPECT_NEAR(ss::topHeight(*scene, book, table), 0.025f, 0.003f);

  // The stage drops the scrap and keeps the book; with no table it cannot tell and keeps both.
  ss::PipelineState state;
  state.cloud = scene;
  state.prepared.has_table = true;
  state.prepared.table_plane = table;
  state.up = Eigen::Vector3f::UnitZ();
  state.segments.resize(2);
  state.segments[0].points = scrap;
  state.segments[1].points = book;
  ss::ObjectSizeParams params;
  ASSERT_FLOAT_EQ(params.min_top_height, 0.015f);
  ss::ObjectSizeStage(params, 0.01f).run(state);
  ASSERT_EQ(state.segments.size(), 1u);
  EXPECT_EQ(state.segments[0].points, book);
  state.prepared.has_table = false;
  state.segments.resize(2);
  state.segments[1].points = scrap;
  ss::ObjectSizeStage(params, 0.01f).run(state);
  EXPECT_EQ(state.segments.size(), 2u);
}
