// A segment that rises from below the table past its edge (a chair's back pushed in to the
// table's end) is no tabletop object; a box flush with the table's front edge is one.
#include <gtest/gtest.h>

#include <algorithm>
#include <string>

#include "symmetry_segmentation/support_polygon.h"
#include "symmetry_segmentation/symmetry/object_size.h"
#include "symmetry_segmentation/symmetry/pipeline_state.h"
#include "symmetry_segmentation/symmetry/rising_segments.h"
#include "test_clouds.h"

namespace ss = symmetry_segmentation;

namespace {

const ss::PlaneCoefficients kTable(0.0f, 0.0f, 1.0f, 0.0f);
constexpr float kMargin = 0.005f;

void add(ss::Cloud& cloud, float x, float y, float z) {
  ss::PointT p;
  p.x = x; p.y = y; p.z = z;
  cloud.push_back(p);
}

/// The scene as a camera over the table's front (y < 0) sees it: a 60 x 40 cm table top at
/// z = 0 and its 3 cm thick front edge (y = -0.2, under the top).
ss::Cloud tableWithItsEdge() {
  ss::Cloud cloud;
  for (float x = -0.3f; x <= 0.3f + 1e-4f; x += 0.01f) {
    for (float y = -0.2f; y <= 0.2f + 1e-4f; y += 0.01f) add(cloud, x, y, 0.0f);
    for (float z = -0.03f; z <= -0.005f; z += 0.005f) add(cloud, x, -0.2f, z);
  }
  return cloud;
}

/// A vertical face at y = `y`, x in [x0, x1], z in [z0, z1]; its indices in `cloud`.
std::vector<int> addFace(ss::Cloud& cloud, float x0, float x1, float y, float z0, float z1) {
  std::vector<int> indices;
  for (float x = x0; x <= x1 + 1e-4f; x += 0.005f) {
    for (float z = z0; z <= z1 + 1e-4f; z += 0.005f) {
      indices.push_back(static_cast<int>(cloud.size()));
      add(cloud, x, y, z);
    }
  }
  return indices;
}

ss::SupportPolygon polygonOf(const ss::Cloud& cloud) {
  const auto polygon = ss::SupportPolygon::fromPlanePoints(cloud, kTable, 0.01f, 0.045f, 0.05f);
  EXPECT_TRUE(polygon.has_value());
  return *polygon;
}

}  // namespace

TEST(RisingSegments, AChairBackPastTheTablesEndRisesFromBelow) {
  // The chair's back stands 2 cm past the table's end (x = 0.3), from the seat 30 cm under the
  // table's top to 15 cm over it; what shows over the top inside the polygon's 5 cm margin
  // (x up to 0.35) is the segment.
  ss::Cloud input = tableWithItsEdge();
  addFace(input, 0.32f, 0.6f, 0.0f, -0.3f, 0.0f);
  const ss::SupportPolygon support = polygonOf(input);
  ss::Cloud working;
  const std::vector<int> back = addFace(working, 0.32f, 0.35f, 0.0f, 0.01f, 0.15f);
  const ss::BelowTableSightings below(input, kTable);
  EXPECT_TRUE(ss::risesFromBelowTable(working, back, kTable, kMargin, support, below, 0.5f));
  EXPECT_FALSE(ss::risesFromBelowTable(working, back, kTable, kMargin, support, below, 0.0f)) << "switched off";

  // A fused map that never saw under the table (kinfu's) has nothing under the back there.
  ss::Cloud fused = tableWithItsEdge();
  fused.erase(std::remove_if(fused.begin(), fused.end(), [](const ss::PointT& p) { return p.z < -0.001f; }), fused.end());
  const ss::BelowTableSightings nothing_below(fused, kTable);
  EXPECT_FALSE(ss::risesFromBelowTable(working, back, kTable, kMargin, polygonOf(fused), nothing_below, 0.5f));
}

TEST(RisingSegments, ABoxNearTheTablesFrontEdgeStandsOnIt) {
  // Its front face (y = -0.17) is 3 cm in from the table's edge, which is seen 0.5-3 cm under the
  // top, and a leg deeper still: nothing under the box's lowest points. (Flush with such an edge,
  // its front face would be past the table's points, which leave out a strip 1.5 cm wide along
  // it, with the edge under it: that box can go, README stage 17.)
  ss::Cloud input = tableWithItsEdge();
  addFace(input, -0.05f, 0.05f, -0.2f, -0.3f, -0.035f);
  ss::Cloud working;
  std::vector<int> box = addFace(working, -0.05f, 0.05f, -0.17f, 0.01f, 0.1f);
  for (float y = -0.17f; y <= -0.07f + 1e-4f; y += 0.005f) {
    for (float x = -0.05f; x <= 0.05f + 1e-4f; x += 0.005f) {
      box.push_back(static_cast<int>(working.size()));
      add(working, x, y, 0.1f);
    }
  }
  const ss::BelowTableSightings below(input, kTable);
  EXPECT_FALSE(ss::risesFromBelowTable(working, box, kTable, kMargin, polygonOf(input), below, 0.5f));
  // The same face 3 cm past the edge, from below the top, is a chair's back.
  ss::Cloud beside = input;
  addFace(beside, -0.05f, 0.05f, -0.23f, -0.3f, 0.0f);
  ss::Cloud shown;
  const std::vector<int> back = addFace(shown, -0.05f, 0.05f, -0.23f, 0.01f, 0.1f);
  EXPECT_TRUE(ss::risesFromBelowTable(shown, back, kTable, kMargin, polygonOf(beside), ss::BelowTableSightings(beside, kTable), 0.5f));
}

TEST(RisingSegments, ObjectSizeDropsTheChairBackAndKeepsTheBox) {
  ss::Scene scene;
  scene.cloud = std::make_shared<ss::Cloud>(tableWithItsEdge());
  addFace(*scene.cloud, 0.32f, 0.6f, 0.0f, -0.3f, 0.0f);
  auto working = std::make_shared<ss::Cloud>();
  const std::vector<int> back = addFace(*working, 0.32f, 0.35f, 0.0f, 0.01f, 0.15f);
  const std::size_t first_box_point = working->size();
  test_clouds::addBox(*working, {-0.05f, -0.05f, 0.01f}, {0.1f, 0.1f, 0.1f}, 0.01f);
  std::vector<int> box;
  for (std::size_t i = first_box_point; i < working->size(); ++i) box.push_back(static_cast<int>(i));

  ss::PipelineState state;
  state.scene = &scene;
  state.cloud = working;
  state.prepared.has_table = true;
  state.prepared.table_plane = kTable;
  state.prepared.table_margin = kMargin;
  state.prepared.support_polygon = polygonOf(*scene.cloud);
  state.up = Eigen::Vector3f::UnitZ();
  state.segments.resize(2);
  state.segments[0].points = back;
  state.segments[1].points = box;
  ss::ObjectSizeParams params;
  ASSERT_GT(params.min_seen_below_share, 0.0f);
  ss::ObjectSizeStage(params, 0.01f).run(state);
  ASSERT_EQ(state.segments.size(), 1u);
  EXPECT_EQ(state.segments[0].points, box);
  const auto rising = std::find_if(state.counts.begin(), state.counts.end(),
                                   [](const auto& count) { return count.first.find("rising") != std::string::npos; });
  ASSERT_NE(rising, state.counts.end());
  EXPECT_EQ(rising->second, 1u);

  params.min_seen_below_share = 0.0f;  // switched off, the back stays
  state.segments.resize(2);
  state.segments[0].points = back;
  state.segments[1].points = box;
  ss::ObjectSizeStage(params, 0.01f).run(state);
  EXPECT_EQ(state.segments.size(), 2u);
}
