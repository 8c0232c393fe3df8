// Completion ground truth (make_scene's whole shapes) and its measures: box IoU, Chamfer distance.
#include <gtest/gtest.h>

#include <algorithm>

#include <Eigen/Geometry>

#include "symmetry_segmentation/evaluation/completion_metric.h"
#include "symmetry_segmentation/scene_io.h"
#include "symmetry_segmentation/segmenter.h"
#include "symmetry_segmentation/synthetic/object_shapes.h"
#include "symmetry_segmentation/synthetic/scene_generator.h"
#include "test_support.h"

namespace ss = symmetry_segmentation;
namespace syn = ss::synthetic;

namespace {

ss::ObjectBox box(const Eigen::Vector3f& center, const Eigen::Vector3f& size, float yaw = 0.0f) {
  ss::ObjectBox b;
  b.center = center;
  b.size = size;
  b.axes = Eigen::AngleAxisf(yaw, Eigen::Vector3f::UnitZ()).toRotationMatrix();
  return b;
}

double median(std::vector<double> values) {
  std::sort(values.begin(), values.end());
  return values[values.size() / 2];
}

}  // namespace

TEST(CompletionMetric, BoxIoUOfKnownOverlaps) {
  const ss::ObjectBox a = box({0, 0, 0}, {0.2f, 0.1f, 0.1f});
  EXPECT_NEAR(ss::boxIoU(a, a), 1.0, 1e-6);
  EXPECT_NEAR(ss::boxIoU(a, box({0.1f, 0, 0}, {0.2f, 0.1f, 0.1f})), 1.0 / 3.0, 0.01);  // half of each
  EXPECT_NEAR(ss::boxIoU(a, box({0, 0, 0}, {0.1f, 0.1f, 0.1f})), 0.5, 0.01);          // one inside the other
  EXPECT_EQ(ss::boxIoU(a, box({1, 0, 0}, {0.2f, 0.1f, 0.1f})), 0.0);
  // The same box described with its axes turned a quarter turn and its sizes swapped.
  EXPECT_NEAR(ss::boxIoU(a, box({0, 0, 0}, {0.1f, 0.2f, 0.1f}, static_cast<float>(M_PI / 2))), 1.0, 0.01);
  EXPECT_EQ(ss::boxIoU(a, box({0, 0, 0}, {0, 0.1f, 0.1f})), 0.0);  // an empty box overlaps nothing
}

TEST(CompletionMetric, ChamferDistanceOfAShiftedSurface) {
  std::vector<Eigen::Vector3f> a, b;
  for (float x = 0; x < 0.1f; x += 0.002f) {
    for (float y = 0; y < 0.1f; y += 0.002f) {
      a.emplace_back(x, y, 0.0f);
      b.emplace_back(x, y, 0.01f);
    }
  }
  EXPECT_NEAR(ss::chamferDistance(a, a), 0.0, 1e-9);
  EXPECT_NEAR(ss::chamferDistance(a, b), 0.01, 1e-5);
  std::vector<Eigen::Vector3f> half(a.begin(), a.begin() + static_cast<long>(a.size() / 2));
  EXPECT_GT(ss::chamferDistance(half, a), 0.005);  // half the surface missing costs, from its side
  EXPECT_TRUE(std::isinf(ss::chamferDistance({}, a)));
}

// make_scene's ground truth in the frame of the cloud it writes (a single view: the camera's),
// and completion against it: on isolated objects seen from one side, their reflections into
// unobserved space bring the points nearer the whole surface.
TEST(CompletionMetric, SingleViewGroundTruthAndCompletionOfIsolatedObjects) {
  syn::GeneratorOptions options;
  options.kind = syn::SceneKind::Isolated;
  options.seed = 3;
  syn::useDepthSensor(options, "kinect");
  const syn::GeneratedScene generated = syn::generate(options);
  const std::string dir = test_support::makeTempDir("completion_truth");
  ss::saveScene(generated.scene, dir);
  syn::saveObjectShapes(generated.layout.world, generated.world_to_scene, dir);
  const std::vector<ss::TrueShape> shapes = ss::loadTrueShapes(dir);
  ASSERT_EQ(shapes.size(), generated.layout.world.objects.size());
  const ss::Scene scene = ss::loadScene(dir);
  for (const ss::TrueShape& shape : shapes) {
    ASSERT_FALSE(shape.surface.empty()) << shape.label;
    // The labelled points the camera saw of the object lie in its true box.
    ss::ObjectBox grown = shape.box;
    grown.size += Eigen::Vector3f::Constant(0.02f);
    std::size_t seen = 0, inside = 0;
    for (std::size_t i = 0; i < scene.labels.size(); ++i) {
      if (scene.labels[i] != shape.label) continue;
      ++seen;
      const Eigen::Vector3f local = grown.axes.transpose() * (scene.cloud->points[i].getVector3fMap() - grown.center);
      inside += (local.cwiseAbs().array() <= 0.5f * grown.size.array()).all() ? 1 : 0;
    }
    if (seen > 0) EXPECT_GT(inside, 0.98 * seen) << shape.label;
  }
  const ss::SegmentationResult result = ss::makeSegmenter("symmetry", ss::SegmentationConfig{})->segment(scene);
  const std::vector<ss::CompletionScore> scores = ss::scoreCompletion(scene, result, shapes);
  ASSERT_GE(scores.size(), 3u);
  std::vector<double> visible, completed, box_iou;
  for (const auto& score : scores) {
    visible.push_back(score.chamfer_visible);
    completed.push_back(score.chamfer_completed);
    box_iou.push_back(score.box_iou_completed);
  }
  EXPECT_LT(median(completed), median(visible));
  EXPECT_GT(median(box_iou), 0.5);
}

TEST(CompletionMetric, ScenesWithoutShapesAndBrokenFilesAreToldApart) {
  const std::string dir = test_support::makeTempDir("completion_truth_bad");
  EXPECT_TRUE(ss::loadTrueShapes(dir).empty());
  test_support::writeTextFile(dir + "/objects.yaml", "objects:\n  - label: 1\n    box: {center: [0, 0], size: [1, 1, 1]}\n");
  EXPECT_THROW(ss::loadTrueShapes(dir), ss::InputError);
  test_support::writeTextFile(dir + "/objects.yaml", "objects: [");
  EXPECT_THROW(ss::loadTrueShapes(dir), ss::InputError);
}
