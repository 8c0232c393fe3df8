// Stage object_size: walls and table remnants are dropped, objects (with a few stray points) stay.
#include <gtest/gtest.h>

#include <algorithm>
#include <numeric>
#include <string>

#include "symmetry_segmentation/symmetry/object_size.h"
#include "symmetry_segmentation/occupancy.h"
#include "symmetry_segmentation/symmetry/pipeline_state.h"
#include "symmetry_segmentation/symmetry/symmetric_graph_cut.h"
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

/// What object_size works on: `working` over `table` (its margin `margin`), the input scene
/// `input` (may be null), and the segments `first` and `second`.
ss::PipelineState overTheTable(const ss::Scene* input, const ss::Cloud::Ptr& working, const ss::PlaneCoefficients& table,
                               float margin, const std::vector<int>& first, const std::vector<int>& second) {
  ss::PipelineState state;
  state.scene = input;
  state.cloud = working;
  state.prepared.has_table = true;
  state.prepared.table_plane = table;
  state.prepared.table_margin = margin;
  state.up = Eigen::Vector3f::UnitZ();
  state.segments.resize(2);
  state.segments[0].points = first;
  state.segments[1].points = second;
  return state;
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
  ss::PipelineState state = overTheTable(nullptr, scene, table, 0.0f, scrap, book);
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

namespace {

/// The table z = 0 seen as a camera sees it: a 0.5 m square of points 5 mm apart, 2 mm over it,
/// except where `hidden(x, y)`.
template <typename Hidden>
void addSeenTable(ss::Cloud& cloud, Hidden hidden) {
  for (float x = -0.25f; x <= 0.25f; x += 0.005f) {
    for (float y = -0.25f; y <= 0.25f; y += 0.005f) {
      if (!hidden(x, y)) cloud.push_back(at(x, y, 0.002f));
    }
  }
}

/// A flat top `height` over the table, points 1 cm apart, over [x0, x1] x [y0, y1].
std::vector<int> addFlatTop(ss::Cloud& cloud, float x0, float x1, float y0, float y1, float height) {
  std::vector<int> points;
  for (float x = x0; x <= x1 + 1e-4f; x += 0.01f) {
    for (float y = y0; y <= y1 + 1e-4f; y += 0.01f) {
      points.push_back(static_cast<int>(cloud.size()));
      cloud.push_back(at(x, y, height));
    }
  }
  return points;
}

}  // namespace

TEST(ObjectSize, AThinObjectHidesTheTableUnderItTheTablesNoiseDoesNot) {
  // A board 1.2 cm thick (table margin 5 mm) lying at x in [-0.2, -0.05] (the table under it
  // never seen) and a patch of the table's noise as high at x in [0.05, 0.2] (the table seen
  // all through it).
  const auto under_board = [](float x, float y) { return x > -0.2f && x < -0.05f && y > -0.1f && y < 0.1f; };
  ss::Scene input;
  input.cloud = std::make_shared<ss::Cloud>();
  addSeenTable(*input.cloud, under_board);
  auto working = std::make_shared<ss::Cloud>();
  const std::vector<int> board = addFlatTop(*working, -0.195f, -0.055f, -0.095f, 0.095f, 0.012f);
  const std::vector<int> scrap = addFlatTop(*working, 0.055f, 0.195f, -0.095f, 0.095f, 0.012f);
  for (int i : board) input.cloud->push_back((*working)[i]);
  for (int i : scrap) input.cloud->push_back((*working)[i]);

  const ss::PlaneCoefficients table(0.0f, 0.0f, 1.0f, 0.0f);
  const ss::TableSightings sightings(*input.cloud, table, 0.005f, 0.01f);
  EXPECT_LT(sightings.seenShareUnder(*working, board).value_or(1.0f), 0.1f);
  EXPECT_GT(sightings.seenShareUnder(*working, scrap).value_or(0.0f), 0.9f);
  // Scattered points (no inner cell of their footprint) tell nothing.
  const std::vector<int> scattered = {board[0], board[40], scrap[0]};
  EXPECT_FALSE(sightings.seenShareUnder(*working, scattered).has_value());

  ss::PipelineState state = overTheTable(&input, working, table, 0.005f, scrap, board);
  ss::ObjectSizeParams params;
  ASSERT_LT(0.012f, params.min_top_height);
  ss::ObjectSizeStage(params, 0.01f).run(state);
  ASSERT_EQ(state.segments.size(), 1u);
  EXPECT_EQ(state.segments[0].points, board);
  // A top within two margins of the table is not clear of its noise (a raised patch of the
  // table hides "the table" too): the board goes with the scrap.
  state.prepared.table_margin = 0.007f;
  state.segments.resize(2);
  state.segments[1].points = scrap;
  ss::ObjectSizeStage(params, 0.01f).run(state);
  EXPECT_TRUE(state.segments.empty());
  // So it does without the exception.
  state.prepared.table_margin = 0.005f;
  params.max_table_seen_share = 0.0f;
  state.segments = {ss::CandidateSegment{}, ss::CandidateSegment{}};
  state.segments[0].points = board;
  state.segments[1].points = scrap;
  ss::ObjectSizeStage(params, 0.01f).run(state);
  EXPECT_TRUE(state.segments.empty());
}

TEST(ObjectSize, AShelfOverTheTableIsNoObjectWhatIsSeenOverAnOccluderIs) {
  // The table seen everywhere but under a box standing at x, y in [-0.2, -0.1]; a shelf board
  // 35 cm over the table at x in [0.05, 0.2] (the table seen under it, from the side), and the
  // top 4 cm of an object behind the box, its lower part hidden by the box, over the box's
  // footprint (the table hidden there too).
  const auto under_box = [](float x, float y) { return x > -0.21f && x < -0.09f && y > -0.21f && y < -0.09f; };
  ss::Scene input;
  input.cloud = std::make_shared<ss::Cloud>();
  addSeenTable(*input.cloud, under_box);
  auto working = std::make_shared<ss::Cloud>();
  const std::vector<int> shelf = addFlatTop(*working, 0.05f, 0.2f, -0.1f, 0.1f, 0.35f);
  std::vector<int> behind = addFlatTop(*working, -0.19f, -0.11f, -0.19f, -0.11f, 0.2f);
  for (int k = 0; k < 4; ++k) {  // its face toward the box, from 16 cm up
    for (float x = -0.19f; x <= -0.11f + 1e-4f; x += 0.01f) {
      behind.push_back(static_cast<int>(working->size()));
      working->push_back(at(x, -0.19f, 0.16f + 0.01f * k));
    }
  }
  for (const auto& point : *working) input.cloud->push_back(point);

  ss::PipelineState state =
      overTheTable(&input, working, ss::PlaneCoefficients(0.0f, 0.0f, 1.0f, 0.0f), 0.005f, shelf, behind);
  ss::ObjectSizeParams params;
  ASSERT_GT(params.min_table_seen_under_raised, 0.0f);
  ss::ObjectSizeStage(params, 0.01f).run(state);
  ASSERT_EQ(state.segments.size(), 1u);
  EXPECT_EQ(state.segments[0].points, behind);
  const auto hanging = std::find_if(state.counts.begin(), state.counts.end(),
                                    [](const auto& count) { return count.first.find("hanging") != std::string::npos; });
  ASSERT_NE(hanging, state.counts.end());
  EXPECT_EQ(hanging->second, 1u);
  // Switched off, the shelf stays.
  params.min_table_seen_under_raised = 0.0f;
  state.segments.resize(2);
  state.segments[1].points = shelf;
  ss::ObjectSizeStage(params, 0.01f).run(state);
  EXPECT_EQ(state.segments.size(), 2u);
}

// Seen from over the table's front, a shelf shades the table under its back: here the table is
// seen under only its front quarter. It still hangs over the table; what is seen over an
// occluder has none of the table under it.
TEST(ObjectSize, AShelfShadingTheTableUnderItIsNoObjectEither) {
  const auto shaded = [](float x, float y) { return x > 0.04f && x < 0.21f && y > -0.05f && y < 0.11f; };
  ss::Scene input;
  input.cloud = std::make_shared<ss::Cloud>();
  addSeenTable(*input.cloud, shaded);
  auto working = std::make_shared<ss::Cloud>();
  const std::vector<int> shelf = addFlatTop(*working, 0.05f, 0.2f, -0.1f, 0.1f, 0.35f);
  for (const auto& point : *working) input.cloud->push_back(point);
  const ss::PlaneCoefficients table(0.0f, 0.0f, 1.0f, 0.0f);
  const float seen = ss::TableSightings(*input.cloud, table, 0.005f, 0.01f).seenShareUnder(*working, shelf).value_or(0.0f);
  ASSERT_GT(seen, 0.15f);
  ASSERT_LT(seen, 0.35f);

  ss::PipelineState state = overTheTable(&input, working, table, 0.005f, shelf, {});
  state.segments.resize(1);
  ss::ObjectSizeParams params;
  ss::ObjectSizeStage(params, 0.01f).run(state);
  EXPECT_TRUE(state.segments.empty());
  // Asking for the table seen under half of it, the shelf stays.
  params.min_table_seen_under_raised = 0.5f;
  state.segments.resize(1);
  state.segments[0].points = shelf;
  ss::ObjectSizeStage(params, 0.01f).run(state);
  EXPECT_EQ(state.segments.size(), 1u);
}

TEST(ObjectSize, AFarScrapOfOneCamerasNoiseStandsHigherThanANearOne) {
  // One camera 1 m over the table, which it sees at a median distance of 1 m. Two patches of
  // the table's noise 3.2 cm high, the table seen through both: one 1 m from the camera, one
  // about 2 m (its noise four times the spread: a scrap up to 6 cm): only the far one is a
  // scrap. In a fused cloud (no table distance) both stay.
  ss::Scene input;
  input.cloud = std::make_shared<ss::Cloud>();
  for (float x = -0.1f; x <= 1.9f; x += 0.005f) {
    for (float y = -0.1f; y <= 0.1f; y += 0.005f) input.cloud->push_back(at(x, y, 0.002f));
  }
  auto working = std::make_shared<ss::Cloud>();
  const std::vector<int> near = addFlatTop(*working, -0.05f, 0.05f, -0.05f, 0.05f, 0.032f);
  const std::vector<int> far = addFlatTop(*working, 1.68f, 1.78f, -0.05f, 0.05f, 0.032f);
  for (const auto& point : *working) input.cloud->push_back(point);

  ss::PipelineState state =
      overTheTable(&input, working, ss::PlaneCoefficients(0.0f, 0.0f, 1.0f, 0.0f), 0.005f, near, far);
  state.prepared.viewpoint = Eigen::Vector3f(0.0f, 0.0f, 1.0f);
  state.prepared.table_range = 1.0f;
  const ss::ObjectSizeParams params;
  ss::ObjectSizeStage(params, 0.01f).run(state);
  ASSERT_EQ(state.segments.size(), 1u);
  EXPECT_EQ(state.segments[0].points, near);

  state.prepared.table_range = 0.0f;
  state.segments.resize(2);
  state.segments[1].points = far;
  ss::ObjectSizeStage(params, 0.01f).run(state);
  EXPECT_EQ(state.segments.size(), 2u);
}

namespace {

// The working cloud of a 10 cm box standing on the table (z = 0), its points, for the specks.
std::shared_ptr<ss::Cloud> boxOnTheTable(std::vector<int>& box) {
  auto working = std::make_shared<ss::Cloud>();
  test_clouds::addBox(*working, {0.0f, 0.0f, -0.005f}, {0.1f, 0.1f, 0.105f}, 0.01f);
  box = allOf(*working);
  return working;
}

// The cut's graph over `working` with a 0.9 m table under it, seen from over its front edge (the
// map goes in the state: the graph reads it).
void addTheCutsGraph(ss::PipelineState& state, const std::shared_ptr<ss::Cloud>& working) {
  ss::Cloud with_table = *working;
  test_clouds::addTable(with_table, 0.9f, 0.01f);
  state.occupancy = std::make_unique<ss::OccupancyMap>(
      ss::OccupancyMap::fromRayCasting(with_table, {Eigen::Vector3f(0.0f, -0.8f, 0.8f)}));
  state.graph = std::make_unique<ss::SymmetricGraphCut>(working, *state.occupancy, ss::PlaneCoefficients(0.0f, 0.0f, 1.0f, 0.0f),
                                                        ss::SymmetryCutParams{});
}

}  // namespace

TEST(ObjectSize, TheTablesSpecksLeaveASegmentOneMadeOfThemGoes) {
  // A 10 cm box, and a chain of the table's specks (1.2 cm over it, 2 cm apart) from 4 cm off
  // its side: the cut's neighbour graph (links up to 5 cm) carries them into the box's segment.
  // A second segment is specks but for three points 5 cm up: mostly specks, it goes whole.
  std::vector<int> box;
  const auto working = boxOnTheTable(box);
  std::vector<int> box_and_specks = box;
  for (float x = 0.14f; x < 0.5f; x += 0.02f) {
    box_and_specks.push_back(static_cast<int>(working->size()));
    working->push_back(at(x, 0.05f, 0.012f));
  }
  std::vector<int> specks_and_a_scrap;
  for (float y = 0.2f; y < 0.6f; y += 0.02f) {
    specks_and_a_scrap.push_back(static_cast<int>(working->size()));
    working->push_back(at(-0.3f, y, 0.012f));
  }
  for (float y = 0.2f; y < 0.23f; y += 0.01f) {
    specks_and_a_scrap.push_back(static_cast<int>(working->size()));
    working->push_back(at(-0.32f, y, 0.05f));
  }
  const ss::PlaneCoefficients table(0.0f, 0.0f, 1.0f, 0.0f);

  ss::PipelineState state = overTheTable(nullptr, working, table, 0.005f, box_and_specks, specks_and_a_scrap);
  const ss::ObjectSizeParams params;
  // Without the cut's graph nothing tells pieces apart: both stay as they are.
  ss::ObjectSizeStage(params, 0.01f).run(state);
  ASSERT_EQ(state.segments.size(), 2u);
  EXPECT_EQ(state.segments[0].points, box_and_specks);

  addTheCutsGraph(state, working);
  ss::ObjectSizeStage(params, 0.01f).run(state);
  ASSERT_EQ(state.segments.size(), 1u);
  EXPECT_EQ(state.segments[0].points, box);
}

TEST(ObjectSize, ABookTheCutJoinedToABoxIsNoSpeck) {
  // The cut joined a box and a book lying flat 4 cm beside it: the book is as low as the table's
  // specks, but it hides the table (seen all round it, never under it), so it stays.
  std::vector<int> box;
  const auto working = boxOnTheTable(box);
  std::vector<int> segment = box;
  for (float x = 0.14f; x < 0.34f; x += 0.01f) {
    for (float y = 0.0f; y < 0.15f; y += 0.01f) {
      segment.push_back(static_cast<int>(working->size()));
      working->push_back(at(x, y, 0.01f));
    }
  }
  ss::Scene input;
  input.cloud = std::make_shared<ss::Cloud>();
  for (float x = -0.4f; x <= 0.6f; x += 0.005f) {
    for (float y = -0.4f; y <= 0.5f; y += 0.005f) {
      const bool under_the_book = x > 0.135f && x < 0.345f && y > -0.005f && y < 0.155f;
      const bool under_the_box = x > -0.005f && x < 0.105f && y > -0.005f && y < 0.105f;
      if (!under_the_book && !under_the_box) input.cloud->push_back(at(x, y, 0.001f));
    }
  }
  for (const auto& point : *working) input.cloud->push_back(point);

  ss::PipelineState state =
      overTheTable(&input, working, ss::PlaneCoefficients(0.0f, 0.0f, 1.0f, 0.0f), 0.005f, segment, {});
  state.segments.resize(1);
  addTheCutsGraph(state, working);
  ss::ObjectSizeStage(ss::ObjectSizeParams{}, 0.01f).run(state);
  ASSERT_EQ(state.segments.size(), 1u);
  EXPECT_EQ(state.segments[0].points, segment);

  // Without the table seen round it, nothing tells the book from a speck: it goes.
  state.scene = nullptr;
  ss::ObjectSizeStage(ss::ObjectSizeParams{}, 0.01f).run(state);
  ASSERT_EQ(state.segments.size(), 1u);
  EXPECT_EQ(state.segments[0].points, box);
}
