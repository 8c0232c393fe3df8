// Stage object_size: walls and table remnants are dropped, objects (with a few stray points) stay.
#include <gtest/gtest.h>

#include <numeric>

#include "symmetry_segmentation/symmetry/object_size.h"
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
