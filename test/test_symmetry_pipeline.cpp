// Stage 4 (plane refinement) and the symmetry method end to end.
#include <gtest/gtest.h>

#include <Eigen/Geometry>

#include "symmetry_segmentation/segmenter.h"
#include "symmetry_segmentation/symmetry/plane_refinement.h"
#include "symmetry_segmentation/symmetry/symmetry_plane.h"
#include "symmetry_segmentation/synthetic/scene_generator.h"
#include "test_clouds.h"

namespace ss = symmetry_segmentation;

TEST(PlaneRefinement, TurnsAPerturbedPlaneBackToTheBoxPlane) {
  ss::Cloud box;
  test_clouds::addBox(box, {0.0f, 0.0f, 0.0f}, {0.12f, 0.08f, 0.10f}, 0.005f);
  std::vector<int> all(box.size());
  for (std::size_t i = 0; i < all.size(); ++i) all[i] = static_cast<int>(i);
  ss::SymmetryPlane truth;
  truth.normal = Eigen::Vector3f::UnitX();
  truth.distance = -0.06f;
  ss::SymmetryPlane perturbed;
  perturbed.normal = Eigen::AngleAxisf(0.07f, Eigen::Vector3f::UnitZ()) * Eigen::Vector3f::UnitX();  // 4 deg
  perturbed.distance = -perturbed.normal.dot(Eigen::Vector3f(0.068f, 0.04f, 0.05f));                  // 8 mm off
  const ss::SymmetryPlane refined =
      ss::refinePlane(box, all, perturbed, ss::SymmetryRefinementParams{}, ss::SymmetryDetectionParams{});
  EXPECT_LT(ss::planeAngleDeg(refined, truth), 1.0f);
  EXPECT_LT(ss::planeDistanceDifference(ss::canonicalPlane(refined), ss::canonicalPlane(truth)), 0.003f);

  ss::SymmetryRefinementParams disabled;
  disabled.enabled = false;
  const auto unchanged = ss::refinePlane(box, all, perturbed, disabled, ss::SymmetryDetectionParams{});
  EXPECT_EQ(unchanged.normal, perturbed.normal);
}

TEST(SymmetryMethod, SameSegmentsWithOneOrTwoThreadsAndPlanesOnEachSegment) {
  ss::synthetic::GeneratorOptions options;
  options.kind = ss::synthetic::SceneKind::Isolated;
  options.seed = 3;
  const ss::Scene scene = ss::synthetic::generateScene(options);

  ss::SegmentationConfig one_thread, two_threads;
  one_thread.symmetry.threads = 1;
  two_threads.symmetry.threads = 2;
  const auto a = ss::makeSegmenter("symmetry", one_thread)->segment(scene);
  const auto b = ss::makeSegmenter("symmetry", two_threads)->segment(scene);
  ASSERT_FALSE(a.segments.empty());
  ASSERT_EQ(a.segments.size(), b.segments.size());
  for (std::size_t i = 0; i < a.segments.size(); ++i) {
    EXPECT_EQ(a.segments[i].indices, b.segments[i].indices);
    ASSERT_TRUE(a.segments[i].symmetry.has_value());
    ASSERT_TRUE(a.segments[i].scores.has_value());
    EXPECT_NEAR(a.segments[i].symmetry->normal.norm(), 1.0f, 1e-4f);
    EXPECT_EQ(a.segments[i].symmetry->normal, b.segments[i].symmetry->normal);
    EXPECT_GT(a.segments[i].scores->occlusion, one_thread.symmetry.filter.s_occl);
    EXPECT_LT(a.segments[i].scores->smoothness, one_thread.symmetry.filter.s_smooth);
  }
  // Each kept segment lies on one object: the method never reports the table.
  for (const auto& segment : a.segments) {
    std::size_t on_table = 0;
    for (int i : segment.indices) on_table += scene.labels[i] == 0;
    EXPECT_LT(on_table, segment.indices.size() / 10);
  }
  std::size_t hypotheses = 0, graph_cuts = 0, before_filtering = 0;
  for (const auto& [name, count] : a.counts) {
    if (name == "hypotheses") hypotheses = count;
    if (name == "graph_cuts") graph_cuts = count;
    if (name == "segments_before_filtering") before_filtering = count;
  }
  EXPECT_GT(hypotheses, 0u);
  // One cut per hypothesis, and at most one more per segment large enough to be refined.
  EXPECT_GT(graph_cuts, hypotheses);
  EXPECT_LE(graph_cuts, 2 * hypotheses);
  EXPECT_GT(before_filtering, 0u);
}
