// Stage occluder_gaps: two pieces of one object, seen either side of a narrower object in front
// of it, get the plane halfway between their outer ends - only when the gap between them is
// hidden, and only when they do not touch.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numeric>

#include <Eigen/Geometry>

#include "symmetry_segmentation/occupancy.h"
#include "symmetry_segmentation/segmentation_config.h"
#include "symmetry_segmentation/symmetry/occluder_gaps.h"
#include "symmetry_segmentation/symmetry/pipeline_state.h"
#include "symmetry_segmentation/symmetry/sorted_indices.h"
#include "test_clouds.h"

namespace ss = symmetry_segmentation;

namespace {

const Eigen::Vector3f kSensor(0.0f, -0.8f, 0.12f);

/// A box 30 cm long behind a post 6 cm wide: the box as the two pieces the sensor sees of it,
/// x in [-0.15, -0.04] and [0.04, 0.15] (the left one 2 cm shorter when `uneven`).
struct BoxBehindAPost {
  ss::Cloud cloud;
  std::vector<int> left, right, post;
  std::vector<Eigen::AlignedBox3f> boxes;

  explicit BoxBehindAPost(bool with_post, float half_gap = 0.04f, bool uneven = false) {
    const float left_end = uneven ? -0.13f : -0.15f;
    test_clouds::addBox(cloud, {left_end, 0.10f, 0.0f}, {-half_gap - left_end, 0.08f, 0.08f}, 0.01f);
    left = range(0, cloud.size());
    boxes.emplace_back(Eigen::Vector3f(left_end, 0.10f, 0.0f), Eigen::Vector3f(-half_gap, 0.18f, 0.08f));
    test_clouds::addBox(cloud, {half_gap, 0.10f, 0.0f}, {0.15f - half_gap, 0.08f, 0.08f}, 0.01f);
    right = range(left.size(), cloud.size());
    boxes.emplace_back(Eigen::Vector3f(half_gap, 0.10f, 0.0f), Eigen::Vector3f(0.15f, 0.18f, 0.08f));
    if (with_post) {
      const std::size_t before = cloud.size();
      test_clouds::addBox(cloud, {-0.03f, -0.06f, 0.0f}, {0.06f, 0.04f, 0.16f}, 0.01f);
      post = range(before, cloud.size());
      boxes.emplace_back(Eigen::Vector3f(-0.03f, -0.06f, 0.0f), Eigen::Vector3f(0.03f, -0.02f, 0.16f));
    }
  }
  static std::vector<int> range(std::size_t from, std::size_t to) {
    std::vector<int> indices(to - from);
    std::iota(indices.begin(), indices.end(), static_cast<int>(from));
    return indices;
  }
  /// The map of what the sensor saw: the objects and the table where no object hides it.
  ss::OccupancyMap occupancy() const {
    ss::Cloud table;
    test_clouds::addTable(table, 1.2f, 0.01f);
    ss::Cloud seen = cloud;
    for (const auto& point : table) {
      if (!hiddenByAnObject(point.getVector3fMap())) seen.push_back(point);
    }
    return ss::OccupancyMap::fromRayCasting(seen, {kSensor});
  }
  bool hiddenByAnObject(const Eigen::Vector3f& point) const {
    return std::any_of(boxes.begin(), boxes.end(),
                       [&](const Eigen::AlignedBox3f& box) { return test_clouds::segmentCrossesBox(kSensor, point, box); });
  }
};

}  // namespace

TEST(OccluderGaps, TwoPiecesEitherSideOfAPostGetThePlaneBetweenTheirOuterEnds) {
  const BoxBehindAPost scene(true);
  const auto hypotheses =
      ss::occluderGapHypothesis(scene.cloud, scene.left, scene.right, scene.occupancy(), ss::OccluderGapParams{});
  ASSERT_EQ(hypotheses.size(), 1u);
  EXPECT_GT(std::fabs(hypotheses[0].plane.normal.x()), 0.999f);
  EXPECT_NEAR(hypotheses[0].plane.distance, 0.0f, 0.005f);
  EXPECT_EQ(hypotheses[0].anchor.size(), scene.left.size() + scene.right.size()) << "anchored on both pieces";
}

TEST(OccluderGaps, TheOuterEndsNotTheCentroidsPlaceThePlane) {
  // The left piece is 2 cm shorter: its centroid moves 1 cm, the middle between the ends 1 cm.
  const BoxBehindAPost scene(true, 0.04f, true);
  const auto hypotheses =
      ss::occluderGapHypothesis(scene.cloud, scene.left, scene.right, scene.occupancy(), ss::OccluderGapParams{});
  ASSERT_EQ(hypotheses.size(), 1u);
  const float x_of_plane = -hypotheses[0].plane.distance / hypotheses[0].plane.normal.x();
  EXPECT_NEAR(x_of_plane, 0.01f, 0.005f);
}

TEST(OccluderGaps, NoPlaneWhereTheGapWasSeenThroughOrThePiecesTouch) {
  // No post: the sensor saw the table through the gap - two objects, not one.
  const BoxBehindAPost open(false);
  EXPECT_TRUE(ss::occluderGapHypothesis(open.cloud, open.left, open.right, open.occupancy(), ss::OccluderGapParams{})
                  .empty());
  // Pieces 1 cm apart touch (a box beside a box): a plane across them is no business of this stage.
  const BoxBehindAPost touching(true, 0.005f);
  EXPECT_TRUE(ss::occluderGapHypothesis(touching.cloud, touching.left, touching.right, touching.occupancy(),
                                        ss::OccluderGapParams{})
                  .empty());
  // Longer together than any object.
  ss::OccluderGapParams short_span;
  short_span.max_span = 0.2f;
  const BoxBehindAPost scene(true);
  EXPECT_TRUE(ss::occluderGapHypothesis(scene.cloud, scene.left, scene.right, scene.occupancy(), short_span).empty());
}

namespace {

/// The prepared view of `scene` (test_clouds::boxBehindAPost) with the long box's two visible
/// pieces as the only candidates (as on real frames, where no curve pair spans the post).
struct PiecesBehindAPost {
  ss::PipelineState state;
  std::vector<int> left, right, box, post;

  PiecesBehindAPost(const ss::Scene& scene, const ss::SegmentationConfig& config) {
    state = ss::preparePipeline(scene, config.preprocessing, config.symmetry);
    for (int v = 0; v < static_cast<int>(state.cloud->size()); ++v) {
      const int input = state.prepared.voxel_to_input[v].front();
      if (scene.labels[input] == 2) post.push_back(v);
      if (scene.labels[input] != 1) continue;
      box.push_back(v);
      const float x = state.cloud->points[v].x;
      if (x < -0.05f) left.push_back(v);
      if (x > 0.05f) right.push_back(v);
    }
    for (const auto* piece : {&left, &right}) {
      ss::SymmetryHypothesis hypothesis;
      hypothesis.plane.normal = Eigen::Vector3f::UnitX();  // each piece's own mid-plane
      hypothesis.plane.distance = -0.5f * (state.cloud->points[piece->front()].x + state.cloud->points[piece->back()].x);
      ss::CandidateSegment candidate;
      candidate.points = *piece;
      candidate.plane = hypothesis.plane;
      candidate.scores.occlusion = 1.0f;
      candidate.scores.smoothness = 0.0f;
      state.hypotheses.push_back(hypothesis);
      state.candidates.push_back(candidate);
    }
  }
};

}  // namespace

TEST(OccluderGaps, TheStageAddsTheCutThatJoinsBothPiecesAndNothingElse) {
  const ss::Scene scene = test_clouds::boxBehindAPost();
  const ss::SegmentationConfig config;
  PiecesBehindAPost pieces(scene, config);
  ss::PipelineState& state = pieces.state;
  const std::vector<int>& right = pieces.right;
  const std::vector<int>& box = pieces.box;
  const std::vector<int>& post = pieces.post;
  ASSERT_GT(pieces.left.size(), 40u);
  ASSERT_GT(right.size(), 40u);
  ss::OccluderGapStage(config.symmetry.occluder_gaps, config.symmetry.filter, config.symmetry.dedup).run(state);
  ASSERT_EQ(state.candidates.size(), 3u);
  ASSERT_EQ(state.hypotheses.size(), 3u) << "hypotheses and candidates stay aligned";
  const ss::CandidateSegment& joined = state.candidates[2];
  EXPECT_NEAR(std::fabs(joined.plane.distance), 0.0f, 0.01f);
  EXPECT_GE(ss::intersectionSize(joined.points, box), static_cast<std::size_t>(0.9 * box.size()));
  EXPECT_TRUE(ss::passesFilter(joined, config.symmetry.filter));

  // A cut that does not take both pieces adds nothing (here: one piece holds a point of the
  // post, which the box's plane does not cut out, and the whole piece is asked for).
  ss::OccluderGapParams strict = config.symmetry.occluder_gaps;
  strict.min_piece_coverage = 1.0f;
  state.candidates.resize(2);
  state.hypotheses.resize(2);
  std::vector<int> right_and_more = right;
  ASSERT_FALSE(post.empty());
  right_and_more.push_back(post.front());
  std::sort(right_and_more.begin(), right_and_more.end());
  state.candidates[1].points = right_and_more;
  ss::OccluderGapStage(strict, config.symmetry.filter, config.symmetry.dedup).run(state);
  EXPECT_EQ(state.candidates.size(), 2u);
}

TEST(OccluderGaps, PiecesOfNoColourInCommonAreTwoObjects) {
  // The same view with the box's left half green and its right half pink: two objects side by
  // side behind the post, as far as anything can tell.
  ss::Scene scene = test_clouds::boxBehindAPost();
  for (std::size_t i = 0; i < scene.cloud->size(); ++i) {
    if (scene.labels[i] != 1) continue;
    ss::PointT& p = scene.cloud->points[i];
    const bool left = p.x < 0.0f;
    p.r = left ? 40 : 230;
    p.g = left ? 170 : 90;
    p.b = left ? 60 : 160;
  }
  const ss::SegmentationConfig config;
  PiecesBehindAPost pieces(scene, config);
  ASSERT_GT(pieces.left.size(), 40u);
  ASSERT_GT(pieces.right.size(), 40u);
  EXPECT_LT(ss::sharedColorShare(*pieces.state.cloud, pieces.left, pieces.right, 15.0f), 0.05f);
  EXPECT_GT(ss::sharedColorShare(*pieces.state.cloud, pieces.left, pieces.left, 15.0f), 0.95f);
  ss::OccluderGapStage(config.symmetry.occluder_gaps, config.symmetry.filter, config.symmetry.dedup).run(pieces.state);
  EXPECT_EQ(pieces.state.candidates.size(), 2u);
  // Colour not asked, the plane across the gap joins them.
  ss::OccluderGapParams geometry_only = config.symmetry.occluder_gaps;
  geometry_only.min_shared_color = 0.0f;
  ss::OccluderGapStage(geometry_only, config.symmetry.filter, config.symmetry.dedup).run(pieces.state);
  EXPECT_EQ(pieces.state.candidates.size(), 3u);
}

TEST(OccluderGaps, PiecesShowingUnequalSharesOfTheWidthGetTheirPlaneTurned) {
  // The same view, but one piece is only the box's front face and the other its front and top:
  // the line between their centroids runs askew across the box, and so does the plane across
  // it. Turned about the up direction, a plane joins them.
  const ss::Scene scene = test_clouds::boxBehindAPost();
  ss::SegmentationConfig config;
  const auto run = [&](const ss::OccluderGapParams& params) {
    ss::PipelineState state = ss::preparePipeline(scene, config.preprocessing, config.symmetry);
    std::vector<int> left, right;
    for (int v = 0; v < static_cast<int>(state.cloud->size()); ++v) {
      if (scene.labels[state.prepared.voxel_to_input[v].front()] != 1) continue;
      const Eigen::Vector3f p = state.cloud->points[v].getVector3fMap();
      if (p.x() < -0.05f && p.y() < 0.105f) left.push_back(v);
      if (p.x() > 0.05f) right.push_back(v);
    }
    for (const auto* piece : {&left, &right}) {
      ss::CandidateSegment candidate;
      candidate.points = *piece;
      candidate.plane.normal = Eigen::Vector3f::UnitX();
      candidate.scores.occlusion = 1.0f;
      state.hypotheses.push_back(ss::SymmetryHypothesis{});
      state.candidates.push_back(candidate);
    }
    ss::OccluderGapStage(params, config.symmetry.filter, config.symmetry.dedup).run(state);
    std::vector<ss::SymmetryPlane> joined;
    for (std::size_t k = 2; k < state.candidates.size(); ++k) joined.push_back(state.candidates[k].plane);
    return joined;
  };
  ss::OccluderGapParams untouched = config.symmetry.occluder_gaps;
  untouched.turn_step_deg = 0.0f;
  EXPECT_TRUE(run(untouched).empty()) << "the askew plane joins them anyway (else this test shows nothing)";
  const auto joined = run(config.symmetry.occluder_gaps);
  ASSERT_FALSE(joined.empty());
  for (const auto& plane : joined) EXPECT_GT(std::fabs(plane.normal.x()), std::cos(25.0f * static_cast<float>(M_PI) / 180.0f));
}
