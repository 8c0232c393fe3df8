// PointCloud2 -> Scene, scene assembly statuses, result -> objects / labelled cloud / markers,
// and parameters from the private namespace. No roscore needed.
#include <gtest/gtest.h>

#include <algorithm>

#include <cmath>
#include <limits>

#include <octomap/OcTree.h>
#include <pcl/point_types.h>
#include <pcl_conversions/pcl_conversions.h>

#include "symmetry_segmentation/SegmentCloud.h"
#include "symmetry_segmentation/errors.h"
#include "symmetry_segmentation/ros/cloud_conversion.h"
#include "symmetry_segmentation/ros/marker_conversion.h"
#include "symmetry_segmentation/parameter_schema.h"
#include "symmetry_segmentation/point_validity.h"
#include "symmetry_segmentation/ros/parameters.h"
#include "symmetry_segmentation/ros/result_conversion.h"
#include "symmetry_segmentation/ros/scene_assembly.h"
#include "symmetry_segmentation/segmentation_output.h"

namespace ss = symmetry_segmentation;
using Response = ss::SegmentCloud::Response;

namespace {

const float kNaN = std::numeric_limits<float>::quiet_NaN();

ss::PointT point(float x, float y, float z, float nx = 0, float ny = 0, float nz = 1) {
  ss::PointT p;
  p.x = x;
  p.y = y;
  p.z = z;
  p.normal_x = nx;
  p.normal_y = ny;
  p.normal_z = nz;
  p.r = 10;
  p.g = 20;
  p.b = 30;
  return p;
}

// A 0.2 x 0.1 x 0.05 grid of points centred on (1, 2, 3), axis-aligned.
ss::Cloud boxCloud() {
  ss::Cloud cloud;
  for (float x = -0.1f; x <= 0.1001f; x += 0.02f) {
    for (float y = -0.05f; y <= 0.0501f; y += 0.025f) {
      for (float z = -0.025f; z <= 0.0251f; z += 0.025f) cloud.push_back(point(1 + x, 2 + y, 3 + z));
    }
  }
  return cloud;
}

sensor_msgs::PointCloud2 xyzMessage(const std::vector<Eigen::Vector3f>& points) {
  pcl::PointCloud<pcl::PointXYZ> cloud;
  for (const auto& p : points) cloud.push_back(pcl::PointXYZ(p.x(), p.y(), p.z()));
  sensor_msgs::PointCloud2 message;
  pcl::toROSMsg(cloud, message);
  message.header.frame_id = "camera";
  return message;
}

uint8_t statusOf(const sensor_msgs::PointCloud2& cloud, const ss::SceneInputs& inputs) {
  try {
    ss::assembleScene(cloud, inputs);
  } catch (const ss::RequestError& error) {
    return error.status();
  }
  return Response::SUCCESS;
}

}  // namespace

TEST(CloudConversion, XyzCloudKeepsOrderAndHasNoNormals) {
  const auto message = xyzMessage({{1, 2, 3}, {kNaN, kNaN, kNaN}, {4, 5, 6}});
  const ss::Scene scene = ss::sceneFromCloudMessage(message);
  ASSERT_EQ(scene.size(), 3u);
  EXPECT_FALSE(scene.has_normals);
  EXPECT_FALSE(scene.has_color);
  EXPECT_FLOAT_EQ(scene.cloud->points[2].y, 5.0f);
  EXPECT_TRUE(std::isnan(scene.cloud->points[1].x));
  EXPECT_EQ(std::count_if(scene.cloud->begin(), scene.cloud->end(), [](const ss::PointT& p) { return ss::isUsablePoint(p); }),
            2);
}

TEST(CloudConversion, NormalsAndColourAreDetected) {
  ss::Cloud cloud;
  cloud.push_back(point(1, 0, 0, 0, 1, 0));
  sensor_msgs::PointCloud2 message;
  pcl::toROSMsg(cloud, message);
  const ss::Scene scene = ss::sceneFromCloudMessage(message);
  EXPECT_TRUE(scene.has_normals);
  EXPECT_TRUE(scene.has_color);
  EXPECT_FLOAT_EQ(scene.cloud->points[0].normal_y, 1.0f);
  EXPECT_EQ(scene.cloud->points[0].g, 20);
}

TEST(CloudConversion, EmptyOrFieldlessCloudsAreInputErrors) {
  EXPECT_THROW(ss::sceneFromCloudMessage(xyzMessage({})), ss::InputError);
  sensor_msgs::PointCloud2 no_xyz = xyzMessage({{1, 2, 3}});
  no_xyz.fields.pop_back();  // drop z
  EXPECT_THROW(ss::sceneFromCloudMessage(no_xyz), ss::InputError);
  sensor_msgs::PointCloud2 short_data = xyzMessage({{1, 2, 3}, {4, 5, 6}});
  short_data.data.resize(short_data.data.size() / 2);
  EXPECT_THROW(ss::sceneFromCloudMessage(short_data), ss::InputError);
}

// The problem text for a message, with the frame id required and an optional point limit.
std::string problemOf(const sensor_msgs::PointCloud2& message, std::size_t max_points = 0) {
  ss::CloudCheckOptions options;
  options.max_points = max_points;
  return ss::cloudMessageProblem(message, options);
}

// True when the problem names every one of `words`.
::testing::AssertionResult names(const std::string& problem, std::initializer_list<const char*> words) {
  for (const char* word : words) {
    if (problem.find(word) == std::string::npos) {
      return ::testing::AssertionFailure() << "'" << problem << "' does not mention '" << word << "'";
    }
  }
  return ::testing::AssertionSuccess();
}

TEST(CloudValidation, AWellFormedCloudHasNoProblem) {
  EXPECT_EQ(problemOf(xyzMessage({{1, 2, 3}, {4, 5, 6}})), "");
  ss::Cloud cloud;
  cloud.push_back(point(1, 0, 0));
  sensor_msgs::PointCloud2 full;
  pcl::toROSMsg(cloud, full);
  full.header.frame_id = "map";
  EXPECT_EQ(problemOf(full), "");
  // An organised cloud with padded rows is fine too.
  sensor_msgs::PointCloud2 padded = xyzMessage({{1, 2, 3}, {4, 5, 6}});
  padded.height = 2;
  padded.width = 1;
  padded.row_step = padded.point_step + 8;
  padded.data.assign(2 * padded.row_step, 0);
  EXPECT_EQ(problemOf(padded), "");
}

TEST(CloudValidation, EmptyFrameIdIsAProblemOnlyWhenRequired) {
  sensor_msgs::PointCloud2 message = xyzMessage({{1, 2, 3}});
  message.header.frame_id.clear();
  EXPECT_TRUE(names(problemOf(message), {"frame_id", "empty"}));
  ss::CloudCheckOptions layout_only;
  layout_only.require_frame = false;
  EXPECT_EQ(ss::cloudMessageProblem(message, layout_only), "");
}

TEST(CloudValidation, EachInconsistentSizeIsNamed) {
  EXPECT_TRUE(names(problemOf(xyzMessage({})), {"empty"}));

  sensor_msgs::PointCloud2 short_data = xyzMessage({{1, 2, 3}, {4, 5, 6}});
  short_data.data.resize(short_data.data.size() - 1);
  EXPECT_TRUE(names(problemOf(short_data), {"data holds", "row_step"}));
  EXPECT_THROW(ss::sceneFromCloudMessage(short_data), ss::InputError);

  sensor_msgs::PointCloud2 long_data = xyzMessage({{1, 2, 3}, {4, 5, 6}});
  long_data.data.resize(long_data.data.size() + 16);
  EXPECT_TRUE(names(problemOf(long_data), {"data holds"}));

  // Width grown without data: width * point_step no longer fits row_step.
  sensor_msgs::PointCloud2 wide = xyzMessage({{1, 2, 3}, {4, 5, 6}});
  wide.width = 3;
  EXPECT_TRUE(names(problemOf(wide), {"row_step", "smaller than width"}));
  EXPECT_THROW(ss::sceneFromCloudMessage(wide), ss::InputError);

  sensor_msgs::PointCloud2 zero_step = xyzMessage({{1, 2, 3}});
  zero_step.point_step = 0;
  zero_step.row_step = 0;
  zero_step.data.clear();
  EXPECT_TRUE(names(problemOf(zero_step), {"point_step is 0"}));

  // A field reaching past the end of a point (z at offset 8 needs 12 bytes).
  sensor_msgs::PointCloud2 narrow = xyzMessage({{1, 2, 3}});
  narrow.point_step = 10;
  narrow.row_step = 10;
  narrow.data.resize(10);
  EXPECT_TRUE(names(problemOf(narrow), {"'z'", "beyond point_step 10"}));
  EXPECT_THROW(ss::sceneFromCloudMessage(narrow), ss::InputError);

  sensor_msgs::PointCloud2 big_endian = xyzMessage({{1, 2, 3}});
  big_endian.is_bigendian = true;
  EXPECT_TRUE(names(problemOf(big_endian), {"big-endian"}));

  // The sizes are multiplied in 64 bits: no wrap-around makes a huge cloud look consistent.
  sensor_msgs::PointCloud2 overflow = xyzMessage({{1, 2, 3}});
  overflow.width = 1u << 31;
  overflow.height = 4;
  overflow.row_step = 0;
  EXPECT_TRUE(names(problemOf(overflow), {"row_step"}));
}

TEST(CloudValidation, XyzFieldsMustBeSingleFloats) {
  sensor_msgs::PointCloud2 no_y = xyzMessage({{1, 2, 3}});
  no_y.fields.erase(no_y.fields.begin() + 1);
  EXPECT_TRUE(names(problemOf(no_y), {"no 'y' field"}));

  sensor_msgs::PointCloud2 doubles = xyzMessage({{1, 2, 3}});
  doubles.fields[0].datatype = sensor_msgs::PointField::FLOAT64;  // x: 8 bytes at 0, still inside the point
  EXPECT_TRUE(names(problemOf(doubles), {"'x'", "FLOAT32"}));
  EXPECT_THROW(ss::sceneFromCloudMessage(doubles), ss::InputError);

  sensor_msgs::PointCloud2 integers = xyzMessage({{1, 2, 3}});
  integers.fields[2].datatype = sensor_msgs::PointField::INT32;
  EXPECT_TRUE(names(problemOf(integers), {"'z'", "FLOAT32"}));

  sensor_msgs::PointCloud2 counted = xyzMessage({{1, 2, 3}});
  counted.fields[0].count = 2;  // x then y: ends within the point
  EXPECT_TRUE(names(problemOf(counted), {"'x'", "count 2"}));

  sensor_msgs::PointCloud2 unknown = xyzMessage({{1, 2, 3}});
  unknown.fields[1].datatype = 42;
  EXPECT_TRUE(names(problemOf(unknown), {"'y'", "unknown datatype 42"}));
}

TEST(CloudValidation, PointLimit) {
  const auto message = xyzMessage({{1, 2, 3}, {4, 5, 6}, {7, 8, 9}});
  EXPECT_EQ(problemOf(message, 3), "");
  EXPECT_TRUE(names(problemOf(message, 2), {"3 points", "limit of 2", "max_input_points"}));
}

TEST(CloudValidation, NormalsOfAnotherTypeAreEstimatedNotReadAsZero) {
  ss::Cloud cloud;
  cloud.push_back(point(1, 0, 0, 0, 1, 0));
  sensor_msgs::PointCloud2 message;
  pcl::toROSMsg(cloud, message);
  for (auto& field : message.fields) {
    if (field.name == "normal_y") field.datatype = sensor_msgs::PointField::INT32;
  }
  EXPECT_FALSE(ss::sceneFromCloudMessage(message).has_normals);
}

TEST(SceneAssembly, LayoutProblemsAreInvalidInput) {
  ss::SceneInputs inputs;
  inputs.sensor_origin = Eigen::Vector3f::Zero();
  sensor_msgs::PointCloud2 wide = xyzMessage({{0, 0, 1}});
  wide.width = 2;
  try {
    ss::assembleScene(wide, inputs);
    ADD_FAILURE() << "accepted a cloud whose row is larger than its data";
  } catch (const ss::RequestError& error) {
    EXPECT_EQ(error.status(), Response::INVALID_INPUT);
    EXPECT_TRUE(names(error.what(), {"row_step"}));
  }
}

TEST(SceneAssembly, MapFromAnotherFrameIsAskedForAroundTheCloud) {
  ss::SceneInputs inputs;
  Eigen::AlignedBox3d asked;
  auto tree = std::make_shared<octomap::OcTree>(0.01);
  inputs.occupancy_for_region = [&](const Eigen::AlignedBox3d& box) {
    asked = box;
    return tree;
  };
  const ss::Scene scene = ss::assembleScene(xyzMessage({{0, 0, 1}, {1, 2, 3}, {kNaN, 0, 0}}), inputs);
  EXPECT_EQ(scene.occupancy, tree);
  EXPECT_TRUE(asked.min().isApprox(Eigen::Vector3d(-ss::kMapMargin, -ss::kMapMargin, 1 - ss::kMapMargin)));
  EXPECT_TRUE(asked.max().isApprox(Eigen::Vector3d(1 + ss::kMapMargin, 2 + ss::kMapMargin, 3 + ss::kMapMargin)));
  inputs.occupancy_for_region = [](const Eigen::AlignedBox3d&) -> std::shared_ptr<octomap::OcTree> {
    throw ss::InputError("too large");
  };
  EXPECT_EQ(statusOf(xyzMessage({{0, 0, 1}}), inputs), Response::INVALID_INPUT);
}

// Found by fuzzing (test/fuzz/corpus/pointcloud2/crash_field_offset): PCL copies every field
// from its offset without checking it against point_step, so a field offset of 16 MB read far
// outside the data.
TEST(CloudConversion, FieldsOutsideThePointAreInputErrors) {
  const auto expectError = [](const sensor_msgs::PointCloud2& message, const std::string& problem) {
    try {
      ss::sceneFromCloudMessage(message);
      ADD_FAILURE() << "accepted, expected an error containing '" << problem << "'";
    } catch (const ss::InputError& error) {
      EXPECT_NE(std::string(error.what()).find(problem), std::string::npos) << error.what();
    }
  };
  const sensor_msgs::PointCloud2 valid = xyzMessage({{1, 2, 3}, {4, 5, 6}});
  ASSERT_EQ(valid.fields.size(), 3u);
  ASSERT_EQ(valid.fields[2].name, "z");
  sensor_msgs::PointCloud2 message = valid;
  message.fields[2].offset = 0x01000003;
  expectError(message, "field 'z' (offset 16777219, 4 bytes) ends beyond point_step");
  message = valid;
  message.fields[2].offset = message.point_step - 2;  // the last 2 of its 4 bytes lie outside
  expectError(message, "field 'z'");
  message = valid;
  message.fields[0].count = 0x40000000;  // 4 GB of floats; 32-bit arithmetic would wrap to 0
  expectError(message, "field 'x'");
  message = valid;
  message.fields[1].datatype = 0;
  expectError(message, "field 'y' has unknown datatype 0");
  message = valid;
  message.fields.push_back(message.fields[2]);
  message.fields.back().name = "intensity";
  message.fields.back().offset = 0xfffffffe;  // offset + size wraps in 32 bits
  expectError(message, "field 'intensity'");
  // A field ending exactly at point_step is fine; the valid message still converts.
  message = valid;
  message.fields[2].offset = message.point_step - 4;
  EXPECT_EQ(ss::sceneFromCloudMessage(message).size(), 2u);
  EXPECT_FLOAT_EQ(ss::sceneFromCloudMessage(valid).cloud->points[1].z, 6.0f);
}

TEST(CloudConversion, TransformMovesPointsAndRotatesNormals) {
  ss::Cloud cloud;
  cloud.push_back(point(1, 0, 0, 1, 0, 0));
  Eigen::Isometry3d transform = Eigen::Isometry3d::Identity();
  transform.rotate(Eigen::AngleAxisd(M_PI / 2, Eigen::Vector3d::UnitZ()));
  transform.pretranslate(Eigen::Vector3d(0, 0, 1));
  ss::transformCloud(cloud, transform, true);
  EXPECT_NEAR(cloud[0].x, 0.0f, 1e-6f);
  EXPECT_NEAR(cloud[0].y, 1.0f, 1e-6f);
  EXPECT_NEAR(cloud[0].z, 1.0f, 1e-6f);
  EXPECT_NEAR(cloud[0].normal_x, 0.0f, 1e-6f);
  EXPECT_NEAR(cloud[0].normal_y, 1.0f, 1e-6f);
}

TEST(CloudConversion, RegionOfInterestIsValidatedAndContains) {
  ss::Scene scene;
  EXPECT_TRUE(scene.inRegionOfInterest(Eigen::Vector3f(2, 0, 0))) << "no region: everything";
  scene.region_of_interest = ss::regionOfInterest(Eigen::Vector3f(-1, -1, -1), Eigen::Vector3f(1, 1, 1));
  EXPECT_TRUE(scene.inRegionOfInterest(Eigen::Vector3f(0, 0, 0)));
  EXPECT_TRUE(scene.inRegionOfInterest(Eigen::Vector3f(1, 1, 1))) << "bounds included";
  EXPECT_FALSE(scene.inRegionOfInterest(Eigen::Vector3f(2, 0, 0)));
  EXPECT_THROW(ss::regionOfInterest(Eigen::Vector3f(1, 0, 0), Eigen::Vector3f(0, 1, 1)), ss::InputError);
  const float nan = std::numeric_limits<float>::quiet_NaN();
  EXPECT_THROW(ss::regionOfInterest(Eigen::Vector3f(nan, 0, 0), Eigen::Vector3f(0, 1, 1)), ss::InputError);
}

// A camera's organized cloud without a sensor frame or a map: the camera fitted to its pixels
// is the viewpoint (and its depth image the occupancy). The same points unorganized are not.
TEST(SceneAssembly, ACameraFrameIsItsOwnViewpoint) {
  const Eigen::Vector3f camera(0.2f, -0.1f, 0.3f);  // where the camera sits in the cloud's frame
  pcl::PointCloud<pcl::PointXYZ> frame(40, 30);
  for (int v = 0; v < 30; ++v) {
    for (int u = 0; u < 40; ++u) {
      const float depth = 1.2f - (std::abs(u - 20) < 6 && std::abs(v - 15) < 6 ? 0.2f : 0.0f);  // a box on a wall
      const Eigen::Vector3f point = camera + depth * Eigen::Vector3f((u - 20) / 40.0f, (v - 15) / 40.0f, 1.0f);
      frame.at(u, v) = pcl::PointXYZ(point.x(), point.y(), point.z());
    }
  }
  sensor_msgs::PointCloud2 message;
  pcl::toROSMsg(frame, message);
  message.header.frame_id = "camera";
  const ss::Scene scene = ss::assembleScene(message, ss::SceneInputs{});
  ASSERT_EQ(scene.sensor_origins.size(), 1u);
  EXPECT_LT((scene.sensor_origins.front() - camera).norm(), 1e-3f);

  std::vector<Eigen::Vector3f> points;
  for (const auto& p : frame.points) points.push_back(p.getVector3fMap());
  EXPECT_EQ(statusOf(xyzMessage(points), ss::SceneInputs{}), Response::NO_OCCUPANCY);
}

TEST(SceneAssembly, StatusPerFailureCause) {
  ss::SceneInputs inputs;
  inputs.sensor_origin = Eigen::Vector3f::Zero();
  EXPECT_EQ(statusOf(xyzMessage({{0, 0, 1}}), inputs), Response::SUCCESS);
  EXPECT_EQ(statusOf(xyzMessage({}), inputs), Response::INVALID_INPUT);
  EXPECT_EQ(statusOf(xyzMessage({{kNaN, kNaN, kNaN}, {kNaN, 0, 1}}), inputs), Response::INVALID_INPUT);
  inputs.region_of_interest = ss::AxisAlignedBox{Eigen::Vector3f(5, 5, 5), Eigen::Vector3f(6, 6, 6)};
  EXPECT_EQ(statusOf(xyzMessage({{0, 0, 1}}), inputs), Response::INVALID_INPUT);
  inputs.region_of_interest.reset();
  inputs.sensor_origin.reset();
  EXPECT_EQ(statusOf(xyzMessage({{0, 0, 1}}), inputs), Response::NO_OCCUPANCY);
  inputs.occupancy = std::make_shared<octomap::OcTree>(0.01);
  EXPECT_EQ(statusOf(xyzMessage({{0, 0, 1}}), inputs), Response::SUCCESS);
  // With a map, a known origin is still passed on (the core orients normals toward it).
  inputs.sensor_origin = Eigen::Vector3f(0, -1, 1);
  const ss::Scene scene = ss::assembleScene(xyzMessage({{0, 0, 1}}), inputs);
  EXPECT_TRUE(scene.occupancy);
  ASSERT_EQ(scene.sensor_origins.size(), 1u);
  EXPECT_FLOAT_EQ(scene.sensor_origins[0].y(), -1.0f);
}

TEST(SceneAssembly, TransformsIntoProcessingFrameAndUsesOrigin) {
  ss::SceneInputs inputs;
  inputs.cloud_to_processing = Eigen::Translation3d(0, 0, 2) * Eigen::Isometry3d::Identity();
  inputs.sensor_origin = Eigen::Vector3f(0, 0, 2);
  const ss::Scene scene = ss::assembleScene(xyzMessage({{0, 0, 1}}), inputs);
  EXPECT_FLOAT_EQ(scene.cloud->points[0].z, 3.0f);
  ASSERT_EQ(scene.sensor_origins.size(), 1u);
  EXPECT_FLOAT_EQ(scene.sensor_origins[0].z(), 2.0f);
  EXPECT_FALSE(scene.occupancy);
  EXPECT_FALSE(scene.up.has_value());  // gravity unknown unless the node has an ~up_frame
  inputs.up = Eigen::Vector3f(0, -1, 0);
  const ss::Scene with_up = ss::assembleScene(xyzMessage({{0, 0, 1}}), inputs);
  ASSERT_TRUE(with_up.up.has_value());
  EXPECT_FLOAT_EQ(with_up.up->y(), -1.0f);
}

TEST(ResultConversion, ObjectBoxesStandOnTheSupportOrComeWithTheSegment) {
  const ss::Cloud cloud = boxCloud();  // 20 x 10 x 5 cm around (1, 2, 3)
  std::vector<int> all(cloud.size());
  for (std::size_t i = 0; i < all.size(); ++i) all[i] = static_cast<int>(i);
  ss::SegmentationResult result;
  ss::Segment segment;
  segment.indices = all;
  result.segments = {segment};
  result.support = ss::SupportSurface{Eigen::Vector4f(1, 0, 0, 0), {}};  // up along x
  std_msgs::Header header;
  const auto message = ss::objectsMessage(cloud, result, header);
  ASSERT_EQ(message.objects.size(), 1u);
  const auto& pose = message.objects[0].bounding_box_pose;
  const Eigen::Quaternionf orientation(pose.orientation.w, pose.orientation.x, pose.orientation.y, pose.orientation.z);
  EXPECT_NEAR(std::abs((orientation * Eigen::Vector3f::UnitZ()).x()), 1.0f, 1e-4f);  // z: the support's up
  EXPECT_NEAR(std::abs((orientation * Eigen::Vector3f::UnitX()).y()), 1.0f, 1e-4f);  // x: the longer footprint side
  EXPECT_NEAR(message.objects[0].bounding_box_size.x, 0.1f, 1e-4f);
  EXPECT_NEAR(message.objects[0].bounding_box_size.y, 0.05f, 1e-4f);
  EXPECT_NEAR(message.objects[0].bounding_box_size.z, 0.2f, 1e-4f);
  EXPECT_NEAR(pose.position.x, 1.0f, 1e-4f);
  EXPECT_NEAR(pose.position.y, 2.0f, 1e-4f);
  EXPECT_NEAR(pose.position.z, 3.0f, 1e-4f);

  ss::ObjectBox given;  // a method's box is handed over as it is
  given.center = Eigen::Vector3f(5, 6, 7);
  given.size = Eigen::Vector3f(0.3f, 0.2f, 0.1f);
  result.segments[0].box = given;
  const auto with_box = ss::objectsMessage(cloud, result, header);
  EXPECT_FLOAT_EQ(with_box.objects[0].bounding_box_pose.position.y, 6.0f);
  EXPECT_FLOAT_EQ(with_box.objects[0].bounding_box_size.x, 0.3f);
  EXPECT_FLOAT_EQ(with_box.objects[0].bounding_box_pose.orientation.w, 1.0f);
}

// The object completed by its symmetry goes out whole: its added points with its own, the
// completed box, the symmetry frame, and a tf frame per object; a printable reply has no clouds.
TEST(ResultConversion, CompletionIsHandedOverWithFramesAndCloudsCanBeLeftOut) {
  const ss::Cloud cloud = boxCloud();
  ss::SegmentationResult result;
  ss::Segment completed;
  completed.indices = {0, 1, 2};
  completed.box = ss::ObjectBox{};
  ss::SegmentCompletion completion;
  completion.points = {Eigen::Vector3f(1.1f, 2.0f, 3.0f), Eigen::Vector3f(1.2f, 2.0f, 3.0f)};
  completion.box.center = Eigen::Vector3f(1.0f, 2.0f, 3.0f);
  completion.box.size = Eigen::Vector3f(0.3f, 0.2f, 0.1f);
  completion.frame_position = Eigen::Vector3f(0.5f, 0.6f, 0.7f);
  completion.frame_orientation = Eigen::Quaternionf(Eigen::AngleAxisf(0.3f, Eigen::Vector3f::UnitZ()));
  completed.completion = completion;
  ss::Segment plain;
  plain.indices = {5, 6};
  plain.box = ss::ObjectBox{};
  plain.box->center = Eigen::Vector3f(9, 8, 7);
  ss::Segment empty;  // no points: no tf frame
  result.segments = {completed, plain, empty};
  std_msgs::Header header;
  header.frame_id = "map";
  header.stamp = ros::Time(7, 0);
  auto message = ss::objectsMessage(cloud, result, header);
  ASSERT_EQ(message.objects.size(), 3u);
  const auto& first = message.objects[0];
  ASSERT_TRUE(first.has_completion);
  EXPECT_EQ(first.completion_points, 2u);
  EXPECT_EQ(first.completed_cloud.width * first.completed_cloud.height, 5u);  // 3 seen + 2 added
  EXPECT_EQ(first.completed_cloud.header.frame_id, "map");
  EXPECT_FLOAT_EQ(first.completed_box_size.x, 0.3f);
  EXPECT_FLOAT_EQ(first.completed_box_pose.position.z, 3.0f);
  EXPECT_FLOAT_EQ(first.symmetry_frame.position.y, 0.6f);
  EXPECT_NEAR(first.symmetry_frame.orientation.z, std::sin(0.15), 1e-6);
  EXPECT_FALSE(message.objects[1].has_completion);

  const auto frames = ss::objectFrames(message);
  ASSERT_EQ(frames.size(), 2u);
  EXPECT_EQ(frames[0].child_frame_id, "object_1");
  EXPECT_EQ(frames[0].header.frame_id, "map");
  EXPECT_EQ(frames[0].header.stamp, ros::Time(7, 0));
  EXPECT_FLOAT_EQ(frames[0].transform.translation.x, 0.5f);  // the symmetry frame
  EXPECT_EQ(frames[1].child_frame_id, "object_2");
  EXPECT_FLOAT_EQ(frames[1].transform.translation.x, 9.0f);  // no completion: the box

  ss::removeClouds(message);
  EXPECT_TRUE(message.objects[0].cloud.data.empty());
  EXPECT_TRUE(message.objects[0].completed_cloud.data.empty());
  EXPECT_EQ(message.objects[0].cloud.header.frame_id, "map");
  EXPECT_EQ(message.objects[0].indices.size(), 3u);
  EXPECT_FLOAT_EQ(message.objects[0].completed_box_size.x, 0.3f);
}

TEST(MarkerConversion, CompletedObjectsShowTheirAddedPointsAndBox) {
  const ss::Cloud cloud = boxCloud();
  ss::SegmentationResult result;
  ss::Segment segment;
  segment.indices = {0, 1, 2};
  ss::SegmentCompletion completion;
  completion.points = {Eigen::Vector3f(1.1f, 2.0f, 3.0f), Eigen::Vector3f(1.2f, 2.0f, 3.0f)};
  completion.box.size = Eigen::Vector3f(0.3f, 0.2f, 0.1f);
  segment.completion = completion;
  result.segments = {segment};
  std_msgs::Header header;
  header.frame_id = "map";
  const auto markers = ss::symmetryMarkers(cloud, result, header);
  auto find = [&](const std::string& ns) {
    return std::find_if(markers.markers.begin(), markers.markers.end(),
                        [&](const visualization_msgs::Marker& m) { return m.ns == ns; });
  };
  const auto added = find("completions");
  ASSERT_NE(added, markers.markers.end());
  EXPECT_EQ(added->type, visualization_msgs::Marker::POINTS);
  EXPECT_EQ(added->id, 1);
  ASSERT_EQ(added->points.size(), 2u);
  EXPECT_NEAR(added->points[1].x, 1.2, 1e-6);
  EXPECT_NEAR(added->color.r, ss::addedPointColor(0).x() / 255.0f, 1e-6);  // as segments_completed.ply
  EXPECT_GT(added->color.r + added->color.g + added->color.b,
            (ss::segmentColor(0).sum()) / 255.0f);  // lighter than the object
  const auto box = find("boxes");
  ASSERT_NE(box, markers.markers.end());
  EXPECT_EQ(box->type, visualization_msgs::Marker::CUBE);
  EXPECT_NEAR(box->scale.x, 0.3, 1e-6);
  EXPECT_LT(box->color.a, 1.0f);
}

TEST(ResultConversion, ObjectsCarryIdsIndicesPlanesAndScores) {
  const ss::Cloud cloud = boxCloud();
  ss::SegmentationResult result;
  ss::Segment with_plane;
  with_plane.indices = {0, 1, 2, 5};
  with_plane.symmetry = ss::SymmetryPlane{Eigen::Vector3f::UnitX(), -1.0f};
  with_plane.scores = ss::SegmentScores{0.995f, 0.01f};
  ss::Segment without_plane;
  without_plane.indices = {7, 8};
  result.segments = {with_plane, without_plane};
  std_msgs::Header header;
  header.frame_id = "map";
  header.stamp = ros::Time(42, 0);
  const auto message = ss::objectsMessage(cloud, result, header);
  EXPECT_EQ(message.header.frame_id, "map");
  ASSERT_EQ(message.objects.size(), 2u);
  const auto& first = message.objects[0];
  EXPECT_EQ(first.id, 1u);
  EXPECT_EQ(first.indices, std::vector<int32_t>({0, 1, 2, 5}));
  EXPECT_EQ(first.cloud.width * first.cloud.height, 4u);
  EXPECT_EQ(first.cloud.header.stamp, ros::Time(42, 0));
  ASSERT_TRUE(first.has_symmetry_plane);
  EXPECT_DOUBLE_EQ(first.symmetry_plane.coef[0], 1.0);
  EXPECT_DOUBLE_EQ(first.symmetry_plane.coef[3], -1.0);
  ASSERT_TRUE(first.has_scores);
  EXPECT_FLOAT_EQ(first.occlusion_score, 0.995f);
  EXPECT_FLOAT_EQ(first.smoothness_score, 0.01f);
  EXPECT_EQ(message.objects[1].id, 2u);
  EXPECT_FALSE(message.objects[1].has_symmetry_plane);
  EXPECT_FALSE(message.objects[1].has_scores);

  const auto empty = ss::objectsMessage(cloud, ss::SegmentationResult{}, header);
  EXPECT_TRUE(empty.objects.empty());
  EXPECT_EQ(empty.header.frame_id, "map");
}

TEST(ResultConversion, LabelledCloudHasLabelsAndSegmentColours) {
  ss::Cloud cloud;
  for (int i = 0; i < 5; ++i) cloud.push_back(point(i, 0, 0));
  cloud[4].x = kNaN;  // dropped
  ss::SegmentationResult result;
  result.segments.resize(2);
  result.segments[0].indices = {1, 2};
  result.segments[1].indices = {2, 3};  // point 2 belongs to the first segment
  std_msgs::Header header;
  header.frame_id = "map";
  const auto message = ss::labelledCloudMessage(cloud, result, header);
  EXPECT_TRUE(ss::hasField(message, "label"));
  EXPECT_TRUE(ss::hasField(message, "rgb") || ss::hasField(message, "rgba"));
  pcl::PointCloud<pcl::PointXYZRGBL> labelled;
  pcl::fromROSMsg(message, labelled);
  ASSERT_EQ(labelled.size(), 4u);
  EXPECT_EQ(labelled[0].label, 0u);
  EXPECT_EQ(labelled[1].label, 1u);
  EXPECT_EQ(labelled[2].label, 1u);
  EXPECT_EQ(labelled[3].label, 2u);
  const Eigen::Vector3i second = ss::segmentColor(1);
  EXPECT_EQ(labelled[3].r, second.x());
  EXPECT_EQ(labelled[3].g, second.y());
  EXPECT_EQ(labelled[3].b, second.z());
}

// A camera's organized cloud comes back in its layout (holes kept), with a mono16 label image
// of the same pixels; an unorganized cloud gets no image.
TEST(ResultConversion, OrganizedCloudKeepsItsLayoutAndGetsALabelImage) {
  ss::Cloud cloud(3, 2);  // pixels 0..5, row-major
  for (int i = 0; i < 6; ++i) cloud[i] = point(i, 0, 1);
  cloud[4].x = kNaN;  // the camera saw nothing there
  ss::SegmentationResult result;
  result.segments.resize(2);
  result.segments[0].indices = {1, 2};
  result.segments[1].indices = {5};
  std_msgs::Header header;
  header.frame_id = "camera_rgb_optical_frame";
  const auto message = ss::labelledCloudMessage(cloud, result, header);
  EXPECT_EQ(message.width, 3u);
  EXPECT_EQ(message.height, 2u);
  pcl::PointCloud<pcl::PointXYZRGBL> labelled;
  pcl::fromROSMsg(message, labelled);
  ASSERT_EQ(labelled.size(), 6u);
  EXPECT_TRUE(std::isnan(labelled[4].x));
  EXPECT_EQ(labelled[4].label, 0u);
  EXPECT_EQ(labelled[2].label, 1u);
  EXPECT_EQ(labelled[5].label, 2u);
  EXPECT_FLOAT_EQ(labelled[5].x, 5.0f);

  const auto image = ss::labelImageMessage(cloud, result, header);
  ASSERT_TRUE(image);
  EXPECT_EQ(image->encoding, "mono16");
  EXPECT_EQ(image->width, 3u);
  EXPECT_EQ(image->height, 2u);
  EXPECT_EQ(image->step, 6u);
  EXPECT_EQ(image->header.frame_id, "camera_rgb_optical_frame");
  ASSERT_EQ(image->data.size(), 12u);
  const std::vector<uint16_t> expected = {0, 1, 1, 0, 0, 2};
  for (std::size_t i = 0; i < expected.size(); ++i) {
    EXPECT_EQ(image->data[2 * i] | (image->data[2 * i + 1] << 8), expected[i]) << "pixel " << i;
  }

  ss::Cloud unorganized = cloud;
  unorganized.width = 6;
  unorganized.height = 1;
  EXPECT_FALSE(ss::labelImageMessage(unorganized, result, header));
}

TEST(MarkerConversion, DeleteAllThenPlanePatchArrowAndText) {
  const ss::Cloud cloud = boxCloud();  // x in [0.9, 1.1], y in [1.95, 2.05], z in [2.975, 3.025]
  std::vector<int> all(cloud.size());
  for (std::size_t i = 0; i < all.size(); ++i) all[i] = static_cast<int>(i);
  ss::SegmentationResult result;
  result.segments.resize(1);
  result.segments[0].indices = all;
  result.segments[0].symmetry = ss::SymmetryPlane{Eigen::Vector3f::UnitX(), -1.0f};  // x = 1
  std_msgs::Header header;
  header.frame_id = "map";
  const auto markers = ss::symmetryMarkers(cloud, result, header);
  ASSERT_EQ(markers.markers.size(), 5u);
  EXPECT_EQ(markers.markers[0].action, visualization_msgs::Marker::DELETEALL);
  const auto& plane = markers.markers[1];
  EXPECT_EQ(plane.type, visualization_msgs::Marker::CUBE);
  EXPECT_EQ(plane.ns, "planes");
  EXPECT_EQ(plane.header.frame_id, "map");
  EXPECT_NEAR(plane.pose.position.x, 1.0, 1e-5);  // on the plane
  EXPECT_NEAR(plane.pose.position.y, 2.0, 1e-4);
  EXPECT_NEAR(plane.pose.position.z, 3.0, 1e-4);
  // Patch spans the object's y (0.1) and z (0.05) extents, in some order.
  const double a = std::max(plane.scale.y, plane.scale.z), b = std::min(plane.scale.y, plane.scale.z);
  EXPECT_NEAR(a, 0.1, 1e-4);
  EXPECT_NEAR(b, 0.05, 1e-4);
  EXPECT_LT(plane.color.a, 1.0f);
  const Eigen::Vector3f segment_color = ss::segmentColor(0).cast<float>() / 255.0f;
  EXPECT_NEAR(plane.color.r, segment_color.x(), 1e-6);
  const auto& arrow = markers.markers[2];
  EXPECT_EQ(arrow.type, visualization_msgs::Marker::ARROW);
  ASSERT_EQ(arrow.points.size(), 2u);
  EXPECT_NEAR(std::abs(arrow.points[1].x - arrow.points[0].x), 0.1, 1e-5);
  EXPECT_NEAR(arrow.points[1].y - arrow.points[0].y, 0.0, 1e-5);
  const auto& text = markers.markers[3];
  EXPECT_EQ(text.type, visualization_msgs::Marker::TEXT_VIEW_FACING);
  EXPECT_EQ(text.text, "1");
  EXPECT_GT(text.pose.position.z, 3.025);
  // Last: the object list above the scene.
  const auto& list = markers.markers[4];
  EXPECT_EQ(list.ns, "object_list");
  EXPECT_EQ(list.type, visualization_msgs::Marker::TEXT_VIEW_FACING);
  EXPECT_EQ(list.text, "1 object\n1: " + std::to_string(cloud.size()) + " points");
  EXPECT_NEAR(list.pose.position.x, 1.0, 1e-4);
  EXPECT_NEAR(list.pose.position.y, 2.0, 1e-4);
  EXPECT_NEAR(list.pose.position.z, 3.025 + 0.2, 1e-4);

  const auto none = ss::symmetryMarkers(cloud, ss::SegmentationResult{}, header);
  ASSERT_EQ(none.markers.size(), 2u);
  EXPECT_EQ(none.markers[0].action, visualization_msgs::Marker::DELETEALL);
  EXPECT_EQ(none.markers[1].text, "0 objects");
  EXPECT_EQ(ss::symmetryMarkers(ss::Cloud(), ss::SegmentationResult{}, header).markers.size(), 1u);

  // The table's extent, when the result has one: a closed outline through its corners.
  ss::SegmentationResult with_support;
  with_support.support = ss::SupportSurface{Eigen::Vector4f(0, 0, 1, -0.7f),
                                            {{0.f, 0.f, 0.7f}, {1.f, 0.f, 0.7f}, {0.5f, 1.f, 0.7f}}};
  const auto outlined = ss::symmetryMarkers(cloud, with_support, header);
  const auto support = std::find_if(outlined.markers.begin(), outlined.markers.end(),
                                    [](const visualization_msgs::Marker& m) { return m.ns == "support"; });
  ASSERT_NE(support, outlined.markers.end());
  EXPECT_EQ(support->type, visualization_msgs::Marker::LINE_STRIP);
  ASSERT_EQ(support->points.size(), 4u);
  EXPECT_NEAR(support->points[1].x, 1.0, 1e-6);
  EXPECT_NEAR(support->points[3].x, support->points[0].x, 1e-9);
  EXPECT_NEAR(support->points[2].z, 0.7, 1e-6);
}

TEST(MarkerConversion, ObjectListCountsUsablePointsAndShowsScores) {
  ss::Cloud cloud = boxCloud();
  cloud[0].x = kNaN;
  ss::SegmentationResult result;
  result.segments.resize(2);
  result.segments[0].indices = {0, 1, 2, 3};
  result.segments[0].scores = ss::SegmentScores{0.9912f, 0.0123f};
  result.segments[1].indices = {4, 5};
  EXPECT_EQ(ss::objectListText(cloud, result),
            "2 objects\n1: 3 points, occlusion 0.991, smoothness 0.012\n2: 2 points");
}

namespace {

bool mentions(const std::vector<std::string>& problems, const std::string& text) {
  for (const auto& problem : problems) {
    if (problem.find(text) != std::string::npos) return true;
  }
  return false;
}

}  // namespace

TEST(Parameters, NestedNamespacesSetTheSameKeysAsTheYamlFile) {
  XmlRpc::XmlRpcValue parameters;
  parameters["symmetry"]["filter"]["s_occl"] = 0.97;
  parameters["symmetry"]["filter"]["min_segment_points"] = 55;
  parameters["symmetry"]["curves"]["min_curve_points"] = 7;
  parameters["preprocessing"]["voxel_size"] = 0.02;
  parameters["mode"] = "on_demand";  // interface parameters are the node's, not the core's
  parameters["fixed_frame"] = "map";
  const auto loaded = ss::algorithmParameters(parameters, {"mode", "fixed_frame"});
  EXPECT_TRUE(loaded.problems.empty()) << loaded.problems.front();
  EXPECT_EQ(loaded.values, 4u);
  EXPECT_FLOAT_EQ(loaded.config.symmetry.filter.s_occl, 0.97f);
  EXPECT_EQ(loaded.config.symmetry.filter.min_segment_points, 55);
  EXPECT_EQ(loaded.config.symmetry.curves.min_curve_points, 7);
  EXPECT_FLOAT_EQ(loaded.config.preprocessing.voxel_size, 0.02f);
  // The same as the YAML file with those values.
  const auto from_yaml = ss::configWithValues(ss::SegmentationConfig(), {{"symmetry.filter.s_occl", "0.97"},
                                                                         {"symmetry.filter.min_segment_points", "55"},
                                                                         {"symmetry.curves.min_curve_points", "7"},
                                                                         {"preprocessing.voxel_size", "0.02"}});
  for (const auto& info : ss::parameterSchema()) {
    EXPECT_EQ(ss::configValueText(loaded.config, info.key), ss::configValueText(from_yaml, info.key)) << info.key;
  }
}

TEST(Parameters, OneBadValueRejectsTheWholeConfigurationNamingEveryProblem) {
  // s_occl 1.5 is out of range: the valid s_smooth is not taken either (defaults in force), and
  // both problems are named.
  XmlRpc::XmlRpcValue parameters;
  parameters["symmetry"]["filter"]["s_occl"] = 1.5;
  parameters["symmetry"]["filter"]["s_smooth"] = 0.05;
  parameters["lccp"]["voxel_resolution"] = 0.1;  // not below seed_resolution 0.04: a rule
  const auto loaded = ss::algorithmParameters(parameters, {});
  ASSERT_FALSE(loaded.problems.empty());
  EXPECT_TRUE(mentions(loaded.problems, "s_occl")) << loaded.problems.front();
  EXPECT_TRUE(mentions(loaded.problems, "voxel_resolution")) << loaded.problems.front();
  const ss::SegmentationConfig defaults;
  EXPECT_FLOAT_EQ(loaded.config.symmetry.filter.s_occl, defaults.symmetry.filter.s_occl);
  EXPECT_FLOAT_EQ(loaded.config.symmetry.filter.s_smooth, defaults.symmetry.filter.s_smooth);
}

TEST(Parameters, UnknownNamesAreProblemsNamedTheRosWay) {
  XmlRpc::XmlRpcValue parameters;
  parameters["symmetry"]["filtr"]["s_occl"] = 0.97;   // a typo in a section
  parameters["symmetry"]["filter"]["s_ocl"] = 0.97;   // a typo in a key
  parameters["sesnor_frame"] = "camera";              // a typo of an interface parameter
  parameters["symmetry"]["filter"]["s_smooth"] = 0.05;
  const auto loaded = ss::algorithmParameters(parameters, {"sensor_frame"});
  EXPECT_EQ(loaded.problems.size(), 3u);
  EXPECT_TRUE(mentions(loaded.problems, "~symmetry/filtr/s_occl"));
  EXPECT_TRUE(mentions(loaded.problems, "~symmetry/filter/s_ocl"));
  EXPECT_TRUE(mentions(loaded.problems, "~sesnor_frame"));
  EXPECT_FLOAT_EQ(loaded.config.symmetry.filter.s_smooth, ss::SegmentationConfig().symmetry.filter.s_smooth)
      << "rejected as a whole";
}

TEST(Parameters, AListParameterIsAYamlList) {
  // symmetry.stages (a string_list) from `rosparam load` arrives as an XmlRpc array.
  XmlRpc::XmlRpcValue parameters;
  const std::vector<std::string> stages = ss::SegmentationConfig().symmetry.stages;
  ASSERT_GT(stages.size(), 2u);
  const std::vector<std::string> fewer(stages.begin(), stages.end() - 1);
  for (std::size_t i = 0; i < fewer.size(); ++i) parameters["symmetry"]["stages"][static_cast<int>(i)] = fewer[i];
  ASSERT_EQ(stages.back(), "completion");  // a stage the list can run without
  const auto loaded = ss::algorithmParameters(parameters, {});
  EXPECT_TRUE(loaded.problems.empty()) << loaded.problems.front();
  EXPECT_EQ(loaded.config.symmetry.stages, fewer);
  XmlRpc::XmlRpcValue bad;
  bad["symmetry"]["stages"][0] = "no_such_stage";
  const auto rejected = ss::algorithmParameters(bad, {});
  ASSERT_FALSE(rejected.problems.empty());
  EXPECT_TRUE(mentions(rejected.problems, "no_such_stage")) << rejected.problems.front();
  EXPECT_EQ(rejected.config.symmetry.stages, stages);
}

TEST(Parameters, ValuesBecomeYamlTextOfTheirType) {
  XmlRpc::XmlRpcValue value = 0.1;
  EXPECT_EQ(ss::parameterText(value), "0.10000000000000001");
  value = 3;
  EXPECT_EQ(ss::parameterText(value), "3");
  value = true;
  EXPECT_EQ(ss::parameterText(value), "true");
  value = "a: b";  // a string stays one string
  EXPECT_EQ(ss::parameterText(value), "\"a: b\"");
  XmlRpc::XmlRpcValue list;
  list[0] = "x";
  list[1] = 2;
  EXPECT_EQ(ss::parameterText(list), "[\"x\", 2]");
  XmlRpc::XmlRpcValue nested;
  nested[0][0] = 1;
  EXPECT_THROW(ss::parameterText(nested), ss::InputError);
}
