// Object bottoms within the table margin: given back to the segment above them, while the
// table itself - facing up, or not linked to any segment - stays out.
#include <gtest/gtest.h>

#include <algorithm>

#include "symmetry_segmentation/object_bottoms.h"
#include "symmetry_segmentation/preprocessing.h"
#include "test_clouds.h"

namespace ss = symmetry_segmentation;

namespace {

bool onBox(const ss::PointT& p) { return p.z > 1e-4f && p.x > -1e-4f && p.x < 0.1001f && p.y > -1e-4f && p.y < 0.0801f; }

struct BoxOnTable {
  ss::Scene scene;
  ss::PreprocessParams params;
  BoxOnTable() {
    scene.cloud = std::make_shared<ss::Cloud>();
    test_clouds::addTable(*scene.cloud, 0.3f, 0.005f);
    // No view sees the table under the box.
    scene.cloud->erase(std::remove_if(scene.cloud->begin(), scene.cloud->end(),
                                      [](const ss::PointT& p) {
                                        return p.z == 0.0f && p.x > -1e-4f && p.x < 0.1001f && p.y > -1e-4f && p.y < 0.0801f;
                                      }),
                       scene.cloud->end());
    test_clouds::addBox(*scene.cloud, {0.0f, 0.0f, 0.0f}, {0.1f, 0.08f, 0.12f}, 0.004f);
    scene.has_normals = true;
    scene.table_plane = ss::PlaneCoefficients(0.0f, 0.0f, 1.0f, 0.0f);
    params.adaptive_table_margin = false;
    params.table_margin = 0.01f;  // the box's two lowest rows (4 and 8 mm) go with the table
  }
  std::vector<int> boxPoints(const ss::PreprocessedScene* kept_by = nullptr) const {
    std::vector<int> points;
    for (std::size_t i = 0; i < scene.cloud->size(); ++i) {
      if (!onBox((*scene.cloud)[i])) continue;
      if (kept_by && kept_by->input_to_voxel[i] < 0) continue;
      points.push_back(static_cast<int>(i));
    }
    return points;
  }
};

/// Table points where `where` holds get a sideways normal (a noisy table's).
template <typename Where>
void faceSideways(BoxOnTable& box, Where where) {
  for (auto& p : box.scene.cloud->points) {
    if (p.z == 0.0f && where(p)) {
      p.normal_x = 1.0f;
      p.normal_z = 0.0f;
    }
  }
}

}  // namespace

TEST(ObjectBottoms, TheStripWithinTheTableMarginRejoinsItsObject) {
  const BoxOnTable box;
  const ss::PreprocessedScene prepared = ss::preprocess(box.scene, box.params);
  std::vector<ss::Segment> segments(1);
  segments[0].indices = box.boxPoints(&prepared);
  const std::size_t kept = segments[0].indices.size();
  const std::vector<int> whole = box.boxPoints();
  ASSERT_LT(kept, whole.size()) << "the margin must have taken some of the box";

  EXPECT_EQ(ss::restoreObjectBottoms(box.scene, prepared, box.params.voxel_size, segments, {}), whole.size() - kept);
  EXPECT_EQ(segments[0].indices, whole) << "every box point and no table point";
}

TEST(ObjectBottoms, TheTableStaysOut) {
  BoxOnTable box;
  // Table points that face sideways (a noisy normal) but lie away from every segment.
  faceSideways(box, [](const ss::PointT& p) { return p.x < -0.1f; });
  const ss::PreprocessedScene prepared = ss::preprocess(box.scene, box.params);
  std::vector<ss::Segment> segments(1);
  segments[0].indices = box.boxPoints(&prepared);
  ss::restoreObjectBottoms(box.scene, prepared, box.params.voxel_size, segments, {});
  EXPECT_EQ(segments[0].indices, box.boxPoints());

  // Without the input's own normals nothing tells sides from table: nothing is added (and a
  // solid box encloses no floor: its strip lies in the footprint's outermost cells).
  segments[0].indices = box.boxPoints(&prepared);
  box.scene.has_normals = false;
  EXPECT_EQ(ss::restoreObjectBottoms(box.scene, prepared, box.params.voxel_size, segments, {}), 0u);
  EXPECT_EQ(segments[0].indices, box.boxPoints(&prepared));
}

TEST(ObjectBottoms, SideFacingTableNoiseBesideTheFootStaysOut) {
  // A strip of table points whose normals face sideways (a camera frame's pixel-grid normals on
  // a noisy table) runs from the box's foot 10 cm out across the table: linked to the box's
  // bottom strip, but not under the box.
  BoxOnTable box;
  faceSideways(box, [](const ss::PointT& p) { return p.x > 0.1001f && p.y > 0.03f && p.y < 0.05f; });
  const ss::PreprocessedScene prepared = ss::preprocess(box.scene, box.params);
  std::vector<ss::Segment> segments(1);
  segments[0].indices = box.boxPoints(&prepared);
  ss::restoreObjectBottoms(box.scene, prepared, box.params.voxel_size, segments, {});
  const std::vector<int> whole = box.boxPoints();
  for (int i : whole) EXPECT_TRUE(std::binary_search(segments[0].indices.begin(), segments[0].indices.end(), i)) << i;
  float farthest = 0.0f;
  for (int i : segments[0].indices) farthest = std::max(farthest, (*box.scene.cloud)[i].x);
  EXPECT_LE(farthest, 0.1f + box.params.voxel_size + 1e-4f) << "no farther out than the link distance past the side";
}

TEST(ObjectBottoms, NothingOutsideTheRegionOfInterestIsAdded) {
  // The region of interest takes only the box's half with x < 5 cm: the bottom strip of the
  // other half, dropped by the margin like the rest, stays out although it touches the segment.
  BoxOnTable box;
  box.scene.region_of_interest = Eigen::AlignedBox3f(Eigen::Vector3f(-0.02f, -0.02f, -0.02f), Eigen::Vector3f(0.05f, 0.1f, 0.2f));
  const ss::PreprocessedScene prepared = ss::preprocess(box.scene, box.params);
  std::vector<ss::Segment> segments(1);
  segments[0].indices = box.boxPoints(&prepared);
  ASSERT_FALSE(segments[0].indices.empty());
  EXPECT_GT(ss::restoreObjectBottoms(box.scene, prepared, box.params.voxel_size, segments, {}), 0u);
  for (int i : segments[0].indices) {
    EXPECT_TRUE(box.scene.region_of_interest->contains((*box.scene.cloud)[i].getVector3fMap())) << i;
  }
}

TEST(ObjectBottoms, ACameraFrameWithoutNormalsGetsThemFromItsPixelGrid) {
  // An organized frame (optical frame: y down, z ahead) of a wall 1 m ahead standing on a floor
  // 0.4 m below the camera, no normals: the wall's foot within the margin comes back, with
  // normals from the pixel grid as the working cloud's; the floor, facing up, stays out. (A 3 cm
  // margin: within about a centimetre of the corner the pixel window blends the floor's normal
  // into the wall's, and those few rows stay out.)
  constexpr int kWidth = 160, kHeight = 200;
  constexpr float kFocal = 300.0f, kCenterRow = 40.0f, kFloorY = 0.4f;
  ss::Scene scene;
  scene.cloud = std::make_shared<ss::Cloud>(kWidth, kHeight);
  for (int v = 0; v < kHeight; ++v) {
    for (int u = 0; u < kWidth; ++u) {
      const Eigen::Vector3f ray((u - kWidth / 2.0f) / kFocal, (v - kCenterRow) / kFocal, 1.0f);
      const float t = ray.y() > 0.0f ? std::min(1.0f, kFloorY / ray.y()) : 1.0f;
      ss::PointT& p = scene.cloud->at(u, v);
      p.getVector3fMap() = t * ray;
      p.r = p.g = p.b = 128;
      p.normal_x = p.normal_y = p.normal_z = NAN;
    }
  }
  scene.has_normals = false;
  scene.sensor_origins = {Eigen::Vector3f::Zero()};
  scene.table_plane = ss::PlaneCoefficients(0.0f, -1.0f, 0.0f, kFloorY);
  ss::PreprocessParams params;
  params.adaptive_table_margin = false;
  params.table_margin = 0.03f;
  params.crop_to_support = false;
  params.background_extent = 0.0f;
  params.max_object_height = 0.0f;
  const auto onWall = [&](int i) { return std::fabs((*scene.cloud)[i].z - 1.0f) < 1e-4f; };
  const ss::PreprocessedScene prepared = ss::preprocess(scene, params);
  ASSERT_FALSE(prepared.table_band_normals.empty());
  ASSERT_EQ(prepared.table_band_normals.size(), prepared.table_band.size());
  std::vector<ss::Segment> segments(1);
  std::size_t wall_in_margin = 0;
  for (int i = 0; i < static_cast<int>(scene.cloud->size()); ++i) {
    if (!onWall(i)) continue;
    if (prepared.input_to_voxel[i] >= 0) segments[0].indices.push_back(i);
    else ++wall_in_margin;
  }
  ASSERT_GT(wall_in_margin, 100u) << "the margin must have taken the wall's foot";
  const std::vector<int> kept = segments[0].indices;
  const std::size_t added = ss::restoreObjectBottoms(scene, prepared, params.voxel_size, segments, {});
  EXPECT_GT(added, wall_in_margin / 2) << "most of the wall's foot comes back";
  for (int i : segments[0].indices) EXPECT_TRUE(onWall(i)) << "a floor point joined the wall";

  // Without pixel-grid normals (a cloud that is no camera frame) nothing tells sides from table.
  ss::PreprocessedScene without = prepared;
  without.table_band.clear();
  without.table_band_normals.clear();
  segments[0].indices = kept;
  EXPECT_EQ(ss::restoreObjectBottoms(scene, without, params.voxel_size, segments, {}), 0u);
}
