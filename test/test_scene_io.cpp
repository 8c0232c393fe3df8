#include <gtest/gtest.h>

#include <fstream>

#include <octomap/OcTree.h>

#include "symmetry_segmentation/scene_io.h"
#include "test_clouds.h"
#include "test_support.h"

namespace ss = symmetry_segmentation;
using test_support::writeTextFile;

namespace {

const char* const kAsciiPly =
    "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\nproperty float z\n"
    "property float nx\nproperty float ny\nproperty float nz\nend_header\n"
    "0 0 1 0 0 -1\n0.1 0 1 0 0 -1\n0 0.1 1 0 0 -1\n";

const char* const kAsciiPcd =
    "# .PCD v0.7\nVERSION 0.7\nFIELDS x y z\nSIZE 4 4 4\nTYPE F F F\nCOUNT 1 1 1\nWIDTH 2\nHEIGHT 1\n"
    "VIEWPOINT 0.5 0.25 1 1 0 0 0\nPOINTS 2\nDATA ascii\n0 0 1\nnan nan nan\n";

}  // namespace

TEST(SceneIo, ReadsPlyWithNormals) {
  const std::string dir = test_support::makeTempDir("scene_io_ply");
  writeTextFile(dir + "/cloud.ply", kAsciiPly);
  const ss::Scene scene = ss::loadScene(dir);
  ASSERT_EQ(scene.size(), 3u);
  EXPECT_TRUE(scene.has_normals);
  EXPECT_FALSE(scene.has_color);
  EXPECT_NEAR(scene.cloud->points[1].x, 0.1f, 1e-6f);
  EXPECT_NEAR(scene.cloud->points[2].normal_z, -1.0f, 1e-6f);
  EXPECT_TRUE(scene.sensor_origins.empty());  // no camera element
  EXPECT_FALSE(scene.occupancy);
  EXPECT_FALSE(scene.table_plane.has_value());
}

TEST(SceneIo, ReadsPcdViewpointAndKeepsNaNPointsInOrder) {
  const std::string dir = test_support::makeTempDir("scene_io_pcd");
  writeTextFile(dir + "/single.pcd", kAsciiPcd);
  const ss::Scene scene = ss::loadScene(dir + "/single.pcd");
  ASSERT_EQ(scene.size(), 2u);
  EXPECT_EQ(scene.name, "single");
  EXPECT_FALSE(scene.has_normals);
  EXPECT_TRUE(std::isnan(scene.cloud->points[1].x));
  ASSERT_EQ(scene.sensor_origins.size(), 1u);
  EXPECT_TRUE(scene.sensor_origins[0].isApprox(Eigen::Vector3f(0.5f, 0.25f, 1.0f)));
}

TEST(SceneIo, SaveAndLoadRoundTrip) {
  ss::Scene scene;
  scene.cloud = std::make_shared<ss::Cloud>();
  test_clouds::addBox(*scene.cloud, {0, 0, 0}, {0.05f, 0.05f, 0.05f}, 0.01f);
  scene.has_normals = true;
  scene.kind = "isolated";
  scene.sensor_origins = {{0.1f, 0.2f, 0.9f}, {-0.3f, 0.2f, 0.8f}};
  scene.up = Eigen::Vector3f(0.0f, -1.0f, 0.0f);
  scene.table_plane = ss::PlaneCoefficients(0, 0, 1, 0.02f);
  scene.labels.assign(scene.cloud->size(), 3);
  scene.labels[0] = 0;
  scene.occupancy = std::make_shared<octomap::OcTree>(0.01);
  scene.occupancy->updateNode(octomap::point3d(0.0f, 0.0f, 0.05f), true);

  const std::string dir = test_support::makeTempDir("scene_io_roundtrip");
  ss::saveScene(scene, dir);
  const ss::Scene loaded = ss::loadScene(dir);
  ASSERT_EQ(loaded.size(), scene.size());
  EXPECT_TRUE(loaded.has_normals);
  EXPECT_EQ(loaded.kind, "isolated");
  EXPECT_EQ(loaded.labels, scene.labels);
  ASSERT_EQ(loaded.sensor_origins.size(), 2u);
  EXPECT_TRUE(loaded.sensor_origins[1].isApprox(scene.sensor_origins[1]));
  ASSERT_TRUE(loaded.up.has_value());
  EXPECT_TRUE(loaded.up->isApprox(Eigen::Vector3f(0.0f, -1.0f, 0.0f)));
  ASSERT_TRUE(loaded.table_plane.has_value());
  EXPECT_NEAR((*loaded.table_plane)[3], 0.02f, 1e-6f);
  ASSERT_TRUE(loaded.occupancy);
  const auto* node = loaded.occupancy->search(0.0, 0.0, 0.05);
  ASSERT_NE(node, nullptr);
  EXPECT_TRUE(loaded.occupancy->isNodeOccupied(node));
  EXPECT_NEAR(loaded.cloud->points[5].normal_z, scene.cloud->points[5].normal_z, 1e-6f);
}

TEST(SceneIo, UpDirectionIsNormalisedAndBadOnesAreRejected) {
  const std::string dir = test_support::makeTempDir("scene_io_up");
  ss::Scene scene;
  scene.cloud = std::make_shared<ss::Cloud>();
  test_clouds::addBox(*scene.cloud, {0, 0, 0}, {0.05f, 0.05f, 0.05f}, 0.01f);
  ss::saveScene(scene, dir);
  EXPECT_FALSE(ss::loadScene(dir).up.has_value());  // not written when unknown
  writeTextFile(dir + "/scene_info.yaml", "up: [0, 0, 2]\n");
  const auto up = ss::loadScene(dir).up;
  ASSERT_TRUE(up.has_value());
  EXPECT_NEAR(up->z(), 1.0f, 1e-6f);
  // Components whose squares overflow a float still give a unit vector (a fuzzer's find).
  writeTextFile(dir + "/scene_info.yaml", "up: [0, -0.8, -5.5e31]\n");
  const auto huge = ss::loadScene(dir).up;
  ASSERT_TRUE(huge.has_value());
  EXPECT_NEAR(huge->norm(), 1.0f, 1e-5f);
  EXPECT_NEAR(huge->z(), -1.0f, 1e-5f);
  for (const char* bad : {"up: [0, 0, 0]\n", "up: [0, 1]\n", "up: [0, x, 1]\n", "up: [0, .nan, 1]\n", "up: 1\n"}) {
    writeTextFile(dir + "/scene_info.yaml", bad);
    EXPECT_THROW(ss::loadScene(dir), ss::InputError) << bad;
  }
}

TEST(SceneIo, PlaneFileIsValidatedAndNormalised) {
  const std::string dir = test_support::makeTempDir("scene_io_plane");
  writeTextFile(dir + "/p.txt", "0 0 2 -1\n");
  const auto plane = ss::loadPlaneFile(dir + "/p.txt");
  EXPECT_NEAR(plane[2], 1.0f, 1e-6f);
  EXPECT_NEAR(plane[3], -0.5f, 1e-6f);
  for (const char* bad : {"0 0 1\n", "0 0 x 1\n", "0 0 0 1\n", "0 0 1 1 5\n", "0 0 inf 1\n"}) {
    writeTextFile(dir + "/bad.txt", bad);
    EXPECT_THROW(ss::loadPlaneFile(dir + "/bad.txt"), ss::InputError) << bad;
  }
}

TEST(SceneIo, LabelsFileIsValidated) {
  const std::string dir = test_support::makeTempDir("scene_io_labels");
  writeTextFile(dir + "/l.txt", "0\n1\n\n2\n");
  EXPECT_EQ(ss::loadLabelsFile(dir + "/l.txt", 3), (std::vector<int>{0, 1, 2}));
  try {
    ss::loadLabelsFile(dir + "/l.txt", 4);
    FAIL() << "count mismatch accepted";
  } catch (const ss::InputError& e) {
    EXPECT_NE(std::string(e.what()).find("has 3 labels but the cloud has 4 points"), std::string::npos);
  }
  for (const char* bad : {"0\n1x\n2\n", "0\n-1\n2\n", "a\nb\nc\n"}) {
    writeTextFile(dir + "/bad.txt", bad);
    EXPECT_THROW(ss::loadLabelsFile(dir + "/bad.txt", 3), ss::InputError) << bad;
  }
}

TEST(SceneIo, OctomapFilesAreValidated) {
  const std::string dir = test_support::makeTempDir("scene_io_octomap");
  octomap::OcTree tree(0.05);
  for (int i = 0; i < 200; ++i) tree.updateNode(octomap::point3d(0.05f * (i % 20), 0.05f * (i / 20), 0.3f), i % 3 != 0);
  ASSERT_TRUE(tree.writeBinaryConst(dir + "/map.bt"));
  ASSERT_TRUE(tree.write(dir + "/map.ot"));
  EXPECT_EQ(ss::loadOctomapFile(dir + "/map.bt")->getNumLeafNodes(), tree.getNumLeafNodes());
  EXPECT_EQ(ss::loadOctomapFile(dir + "/map.ot")->getNumLeafNodes(), tree.getNumLeafNodes());

  for (const std::string ext : {".bt", ".ot"}) {
    const std::string whole = test_support::readTextFile(dir + "/map" + ext);
    writeTextFile(dir + "/truncated" + ext, whole.substr(0, whole.size() * 2 / 3));
    EXPECT_THROW(ss::loadOctomapFile(dir + "/truncated" + ext), ss::InputError) << ext;
    writeTextFile(dir + "/garbage" + ext, "not an octomap at all\n");
    EXPECT_THROW(ss::loadOctomapFile(dir + "/garbage" + ext), ss::InputError) << ext;
  }
  EXPECT_THROW(ss::loadOctomapFile(dir + "/missing.bt"), ss::InputError);

  octomap::OcTree empty(0.02);
  ASSERT_TRUE(empty.writeBinaryConst(dir + "/empty.bt"));
  const auto loaded_empty = ss::loadOctomapFile(dir + "/empty.bt");
  EXPECT_EQ(loaded_empty->size(), 0u);
  EXPECT_DOUBLE_EQ(loaded_empty->getResolution(), 0.02);
  writeTextFile(dir + "/color.bt", "# Octomap OcTree binary file\nid ColorOcTree\nsize 1\nres 0.01\ndata\n");
  EXPECT_THROW(ss::loadOctomapFile(dir + "/color.bt"), ss::InputError);
  writeTextFile(dir + "/badres.bt", "# Octomap OcTree binary file\nid OcTree\nsize 1\nres -1\ndata\n");
  EXPECT_THROW(ss::loadOctomapFile(dir + "/badres.bt"), ss::InputError);
}
