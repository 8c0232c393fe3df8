#include <gtest/gtest.h>

#include "symmetry_segmentation/errors.h"
#include "symmetry_segmentation/segmenter.h"
#include "test_clouds.h"

namespace ss = symmetry_segmentation;

namespace {

// Two boxes on a table, no face of one flush with a face of the other; `gap` is the free
// space between them along x. labels: 0 table, 1, 2 boxes.
// Touching boxes hide their contact faces, so those points are left out as a sensor would.
ss::Scene twoBoxes(float gap) {
  ss::Cloud all;
  std::vector<int> labels;
  test_clouds::addTable(all, 0.5f, 0.005f);
  labels.resize(all.size(), 0);
  test_clouds::addBox(all, {-0.12f, 0.0f, 0.0f}, {0.12f, 0.1f, 0.15f}, 0.004f);
  labels.resize(all.size(), 1);
  test_clouds::addBox(all, {gap, 0.02f, 0.0f}, {0.1f, 0.12f, 0.1f}, 0.004f);
  labels.resize(all.size(), 2);
  ss::Scene scene;
  scene.cloud = std::make_shared<ss::Cloud>();
  for (std::size_t i = 0; i < all.size(); ++i) {
    const auto& p = all.points[i];
    const bool hidden_contact = gap == 0.0f && std::fabs(p.x) < 1e-4f && p.z < 0.1f && p.y >= 0.02f && p.y <= 0.1f;
    if (hidden_contact) continue;
    scene.cloud->push_back(p);
    scene.labels.push_back(labels[i]);
  }
  scene.has_normals = true;
  scene.table_plane = ss::PlaneCoefficients(0, 0, 1, 0);
  scene.sensor_origins.push_back({0.0f, -0.7f, 0.7f});
  return scene;
}

// Fraction of the points labelled `label` that lie in `segment`.
double coverage(const ss::Segment& segment, const ss::Scene& scene, int label) {
  std::size_t inside = 0;
  for (int i : segment.indices) inside += scene.labels[i] == label;
  return static_cast<double>(inside) /
         static_cast<double>(std::count(scene.labels.begin(), scene.labels.end(), label));
}

}  // namespace

TEST(Baselines, EuclideanSeparatesSeparatedBoxesAndMergesTouchingOnes) {
  const ss::Scene separated = twoBoxes(0.08f);
  const auto segmenter = ss::makeSegmenter("euclidean", ss::SegmentationConfig{});
  const auto result = segmenter->segment(separated);
  EXPECT_EQ(result.input_points, separated.size());
  ASSERT_EQ(result.segments.size(), 2u);
  // Largest first: the first box has more points.
  EXPECT_GT(coverage(result.segments[0], separated, 1), 0.85);
  EXPECT_GT(coverage(result.segments[1], separated, 2), 0.85);
  EXPECT_EQ(coverage(result.segments[0], separated, 2), 0.0);
  EXPECT_FALSE(result.segments[0].symmetry.has_value());
  EXPECT_EQ(result.timing_ms.back().first, "total");

  const ss::Scene touching = twoBoxes(0.0f);
  EXPECT_EQ(segmenter->segment(touching).segments.size(), 1u);  // why users need more than this
}

TEST(Baselines, LccpSeparatesTouchingBoxesAtTheConcaveEdge) {
  const ss::Scene touching = twoBoxes(0.0f);
  const auto result = ss::makeSegmenter("lccp", ss::SegmentationConfig{})->segment(touching);
  ASSERT_GE(result.segments.size(), 2u);
  bool first_found = false, second_found = false;
  for (const auto& segment : result.segments) {
    first_found |= coverage(segment, touching, 1) > 0.9 && coverage(segment, touching, 2) < 0.05;
    second_found |= coverage(segment, touching, 2) > 0.9 && coverage(segment, touching, 1) < 0.05;
  }
  EXPECT_TRUE(first_found);
  EXPECT_TRUE(second_found);
  // Every method's segments come with their boxes, standing on the table.
  for (const auto& segment : result.segments) {
    ASSERT_TRUE(segment.box.has_value());
    EXPECT_GT(segment.box->axes.col(2).z(), 0.999f);
    EXPECT_GE(segment.box->size.x(), segment.box->size.y());
    for (int i : segment.indices) {  // holding the segment's points
      const Eigen::Vector3f local =
          segment.box->axes.transpose() * (touching.cloud->points[i].getVector3fMap() - segment.box->center);
      EXPECT_TRUE((local.cwiseAbs().array() <= 0.5f * segment.box->size.array() + 1e-4f).all());
    }
  }
}

TEST(Baselines, UnknownMethodIsAnError) {
  EXPECT_THROW(ss::makeSegmenter("magic", ss::SegmentationConfig{}), ss::InputError);
  const auto methods = ss::availableMethods();
  EXPECT_NE(std::find(methods.begin(), methods.end(), ss::defaultMethod()), methods.end());
}
