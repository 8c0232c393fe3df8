// The node's ROS-free parts: the newest-item worker of continuous mode, the moved-map cache and
// the table plane's check and transform; and that they stay ROS-free.
#include <gtest/gtest.h>

#include <atomic>
#include <chrono>
#include <cmath>
#include <condition_variable>
#include <fstream>
#include <memory>
#include <mutex>
#include <regex>
#include <set>
#include <string>
#include <thread>
#include <vector>

#include <octomap/OcTree.h>

#include "symmetry_segmentation/errors.h"
#include "symmetry_segmentation/ros/moved_map_cache.h"
#include "symmetry_segmentation/ros/newest_item_worker.h"
#include "symmetry_segmentation/ros/table_plane.h"

namespace ss = symmetry_segmentation;

namespace {

// Every header a source file includes, following the package's own headers. Debian installs ROS
// under /usr/include, so a compiler cannot tell us: the include lines are read instead.
void collectIncludes(const std::string& path, std::set<std::string>& seen, std::set<std::string>& headers) {
  if (!seen.insert(path).second) return;
  std::ifstream file(path);
  ASSERT_TRUE(file) << "cannot read " << path;
  static const std::regex include_line(R"(^\s*#\s*include\s*[<"]([^>"]+)[>"])");
  std::string line;
  std::smatch match;
  while (std::getline(file, line)) {
    if (!std::regex_search(line, match, include_line)) continue;
    const std::string header = match[1];
    headers.insert(header);
    if (header.rfind("symmetry_segmentation/", 0) == 0) {
      collectIncludes(std::string(SOURCE_DIR) + "/include/" + header, seen, headers);
    }
  }
}

}  // namespace

TEST(NodeParts, IncludeNoRosHeader) {
  std::set<std::string> seen, headers;
  for (const char* file : {"include/symmetry_segmentation/ros/newest_item_worker.h",
                           "include/symmetry_segmentation/ros/moved_map_cache.h", "src/ros/moved_map_cache.cpp",
                           "include/symmetry_segmentation/ros/table_plane.h", "src/ros/table_plane.cpp"}) {
    collectIncludes(std::string(SOURCE_DIR) + "/" + file, seen, headers);
  }
  EXPECT_GT(headers.count("octomap/OcTree.h") + headers.count("Eigen/Geometry"), 0u) << "the scan found nothing";
  static const std::regex ros_header(
      R"(^(ros/|roscpp|rosbag|nodelet|pluginlib|tf2|dynamic_reconfigure|diagnostic_|message_filters|pcl_conversions|xmlrpcpp|[a-z_]+_msgs/|symmetry_segmentation/[A-Z]))");
  for (const auto& header : headers) {
    EXPECT_FALSE(std::regex_search(header, ros_header)) << header << " is a ROS header";
  }
}

namespace {

// Spins until `done` (true) or 10 s pass (false).
template <class Predicate>
bool waitFor(Predicate done) {
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(10);
  while (!done()) {
    if (std::chrono::steady_clock::now() > deadline) return false;
    std::this_thread::sleep_for(std::chrono::milliseconds(1));
  }
  return true;
}

// A handler that blocks until released, recording what it was given.
struct Gate {
  std::mutex mutex;
  std::condition_variable changed;
  bool open = false;
  std::vector<int> seen;
  void handle(int& item) {
    std::unique_lock<std::mutex> lock(mutex);
    seen.push_back(item);
    changed.wait(lock, [this] { return open; });
  }
  void release() {
    {
      std::lock_guard<std::mutex> lock(mutex);
      open = true;
    }
    changed.notify_all();
  }
  std::size_t count() {
    std::lock_guard<std::mutex> lock(mutex);
    return seen.size();
  }
};

}  // namespace

TEST(NewestItemWorker, HandlesEveryItemWhenIdle) {
  std::mutex mutex;
  std::vector<int> seen;
  ss::NewestItemWorker<int> worker([&](int& item) {
    std::lock_guard<std::mutex> lock(mutex);
    seen.push_back(item);
  });
  for (int i = 0; i < 3; ++i) {
    worker.push(i);
    ASSERT_TRUE(waitFor([&] { return worker.handled() == static_cast<std::size_t>(i + 1); }));
  }
  EXPECT_EQ(seen, (std::vector<int>{0, 1, 2}));
  EXPECT_EQ(worker.dropped(), 0u);
  EXPECT_FALSE(worker.busy());
}

TEST(NewestItemWorker, WhileBusyTheNewestReplacesTheWaitingOneAndDropsAreCounted) {
  Gate gate;
  ss::NewestItemWorker<int> worker([&](int& item) { gate.handle(item); });
  worker.push(1);
  ASSERT_TRUE(waitFor([&] { return gate.count() == 1; }));  // 1 is in the handler
  for (int i = 2; i <= 5; ++i) worker.push(i);              // 2, 3, 4 replaced in turn by 5
  EXPECT_EQ(worker.dropped(), 3u);
  EXPECT_TRUE(worker.busy());
  gate.release();
  ASSERT_TRUE(waitFor([&] { return worker.handled() == 2; }));
  EXPECT_EQ(gate.seen, (std::vector<int>{1, 5}));
  EXPECT_FALSE(worker.busy());
}

TEST(NewestItemWorker, ClearWithdrawsTheWaitingItemAndStopJoins) {
  Gate gate;
  auto worker = std::make_unique<ss::NewestItemWorker<int>>([&](int& item) { gate.handle(item); });
  worker->push(1);
  ASSERT_TRUE(waitFor([&] { return gate.count() == 1; }));
  worker->push(2);
  worker->clear();
  EXPECT_EQ(worker->dropped(), 0u) << "a withdrawn item was not overtaken";
  std::thread release([&] {
    std::this_thread::sleep_for(std::chrono::milliseconds(50));
    gate.release();
  });
  worker->stop();  // waits for the item in progress
  release.join();
  EXPECT_EQ(worker->handled(), 1u);
  worker->push(3);  // ignored after stop
  worker.reset();   // a second stop in the destructor is harmless
  EXPECT_EQ(gate.seen, (std::vector<int>{1}));
}

// ~max_rate: a fast stream is handled at most once per period, always its newest item. The
// upper bound holds however loaded the machine is; the lower one only asks that it runs at all.
TEST(NewestItemWorker, AMinimumPeriodLimitsTheRateAndKeepsTheNewest) {
  std::mutex mutex;
  std::vector<int> seen;
  ss::NewestItemWorker<int> worker([&](int& item) {
    std::lock_guard<std::mutex> lock(mutex);
    seen.push_back(item);
  });
  worker.setMinPeriod(std::chrono::milliseconds(200));
  const auto start = std::chrono::steady_clock::now();
  int pushed = 0;
  while (std::chrono::steady_clock::now() - start < std::chrono::milliseconds(1000)) {
    worker.push(pushed++);
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  }
  const int last = pushed - 1;
  ASSERT_TRUE(waitFor([&] { return !worker.busy(); }));
  const auto elapsed = std::chrono::steady_clock::now() - start;
  std::lock_guard<std::mutex> lock(mutex);
  const auto periods = std::chrono::duration_cast<std::chrono::milliseconds>(elapsed).count() / 200;
  EXPECT_LE(static_cast<long>(seen.size()), periods + 1) << "more than one item per period";
  EXPECT_GE(seen.size(), 2u);
  EXPECT_GT(pushed, 20);
  EXPECT_EQ(seen.back(), last) << "the newest item is the one handled";
  EXPECT_EQ(worker.dropped() + worker.handled(), static_cast<std::size_t>(pushed));
}

namespace {

std::shared_ptr<octomap::OcTree> smallMap() {
  auto tree = std::make_shared<octomap::OcTree>(0.05);
  tree->updateNode(octomap::point3d(0.1f, 0.1f, 0.1f), true);
  return tree;
}

}  // namespace

TEST(MovedMapCache, BuildsOnceForTheSameMapFrameAndTransformWithinTheRegion) {
  std::vector<Eigen::AlignedBox3d> regions;
  ss::MovedMapCache cache(
      [&](const octomap::OcTree& source, const Eigen::Isometry3d&, const Eigen::AlignedBox3d& region) {
        regions.push_back(region);
        return std::make_shared<octomap::OcTree>(source.getResolution());
      },
      0.25);
  const auto map = smallMap();
  const Eigen::Isometry3d motion(Eigen::Translation3d(1, 0, 0));
  const Eigen::AlignedBox3d box(Eigen::Vector3d(0, 0, 0), Eigen::Vector3d(1, 1, 1));
  const auto first = cache.get(map, "map", motion, box);
  ASSERT_EQ(regions.size(), 1u);
  EXPECT_TRUE(regions[0].isApprox(Eigen::AlignedBox3d(Eigen::Vector3d::Constant(-0.25), Eigen::Vector3d::Constant(1.25))))
      << "the slack is added around the box";
  // A slightly different box within the slack: the same copy.
  const Eigen::AlignedBox3d nudged(Eigen::Vector3d(-0.1, 0, 0), Eigen::Vector3d(1.1, 1, 1));
  EXPECT_EQ(cache.get(map, "map", motion, nudged), first);
  EXPECT_EQ(cache.builds(), 1u);
  // Another frame, another transform, a box beyond the region or another map: built anew.
  cache.get(map, "odom", motion, box);
  EXPECT_EQ(cache.builds(), 2u);
  cache.get(map, "odom", Eigen::Isometry3d(Eigen::Translation3d(2, 0, 0)), box);
  EXPECT_EQ(cache.builds(), 3u);
  cache.get(map, "odom", Eigen::Isometry3d(Eigen::Translation3d(2, 0, 0)),
            Eigen::AlignedBox3d(Eigen::Vector3d(0, 0, 0), Eigen::Vector3d(2, 1, 1)));
  EXPECT_EQ(cache.builds(), 4u);
  const auto other = smallMap();
  cache.get(other, "odom", Eigen::Isometry3d(Eigen::Translation3d(2, 0, 0)), box);
  EXPECT_EQ(cache.builds(), 5u);
  // Cleared: built again even for the same request.
  cache.clear();
  cache.get(other, "odom", Eigen::Isometry3d(Eigen::Translation3d(2, 0, 0)), box);
  EXPECT_EQ(cache.builds(), 6u);
}

TEST(MovedMapCache, AFailedBuildCachesNothing) {
  bool fail = true;
  ss::MovedMapCache cache(
      [&](const octomap::OcTree& source, const Eigen::Isometry3d&, const Eigen::AlignedBox3d&) {
        if (fail) throw ss::InputError("region too large");
        return std::make_shared<octomap::OcTree>(source.getResolution());
      },
      0.0);
  const auto map = smallMap();
  const Eigen::AlignedBox3d box(Eigen::Vector3d(0, 0, 0), Eigen::Vector3d(1, 1, 1));
  EXPECT_THROW(cache.get(map, "map", Eigen::Isometry3d::Identity(), box), ss::InputError);
  fail = false;
  EXPECT_NE(cache.get(map, "map", Eigen::Isometry3d::Identity(), box), nullptr);
  EXPECT_EQ(cache.builds(), 1u);
}

TEST(MovedMapCache, ReleasesTheOldCopyBeforeBuildingTheNext) {
  std::weak_ptr<octomap::OcTree> previous;
  bool previous_alive_during_build = false;
  ss::MovedMapCache cache(
      [&](const octomap::OcTree& source, const Eigen::Isometry3d&, const Eigen::AlignedBox3d&) {
        previous_alive_during_build = !previous.expired();
        return std::make_shared<octomap::OcTree>(source.getResolution());
      },
      0.0);
  const auto map = smallMap();
  const Eigen::AlignedBox3d box(Eigen::Vector3d(0, 0, 0), Eigen::Vector3d(1, 1, 1));
  previous = cache.get(map, "map", Eigen::Isometry3d::Identity(), box);
  cache.get(map, "odom", Eigen::Isometry3d::Identity(), box);
  EXPECT_FALSE(previous_alive_during_build) << "two moved maps in memory at once";
}

TEST(TablePlane, CoefficientsAreCheckedAndNormalised) {
  const Eigen::Vector4d plane = ss::planeFromCoefficients({0, 0, 2, -1});
  EXPECT_TRUE(plane.isApprox(Eigen::Vector4d(0, 0, 1, -0.5)));
  EXPECT_THROW(ss::planeFromCoefficients({0, 0, 1}), ss::InputError);
  EXPECT_THROW(ss::planeFromCoefficients({0, 0, 1, 0, 0}), ss::InputError);
  EXPECT_THROW(ss::planeFromCoefficients({0, 0, 0, 1}), ss::InputError);
  EXPECT_THROW(ss::planeFromCoefficients({0, NAN, 1, 0}), ss::InputError);
  EXPECT_THROW(ss::planeFromCoefficients({0, 0, 1, INFINITY}), ss::InputError);
  EXPECT_THROW(ss::planeFromCoefficients({0, 0, 1e-300, 1}), ss::InputError) << "d / |n| is 1e300 m";
  EXPECT_TRUE(ss::planeFromCoefficients({0, 0, 1e200, -1e200}).isApprox(Eigen::Vector4d(0, 0, 1, -1)));
  EXPECT_TRUE(ss::planeFromCoefficients({0, 3e-200, 4e-200, 0}).isApprox(Eigen::Vector4d(0, 0.6, 0.8, 0)));
  try {
    ss::planeFromCoefficients({1, 2});
    FAIL();
  } catch (const ss::InputError& error) {
    EXPECT_NE(std::string(error.what()).find("got 2"), std::string::npos) << error.what();
  }
}

TEST(TablePlane, TransformKeepsPointsOnThePlaneAndTheNormalUnit) {
  // The table z = 0.7 in a camera frame; the camera in "map" turned and moved arbitrarily.
  const Eigen::Vector4d in_camera = ss::planeFromCoefficients({0, 0, 1, -0.7});
  Eigen::Isometry3d camera_to_map = Eigen::Isometry3d::Identity();
  camera_to_map.rotate(Eigen::AngleAxisd(0.8, Eigen::Vector3d(1, -2, 0.5).normalized()));
  camera_to_map.pretranslate(Eigen::Vector3d(0.3, -1.2, 2.0));
  const Eigen::Vector4d in_map = ss::transformPlane(in_camera, camera_to_map);
  EXPECT_NEAR(in_map.head<3>().norm(), 1.0, 1e-12);
  EXPECT_TRUE(in_map.head<3>().isApprox(camera_to_map.rotation() * Eigen::Vector3d::UnitZ(), 1e-12));
  for (const Eigen::Vector3d& on_plane : {Eigen::Vector3d(0, 0, 0.7), Eigen::Vector3d(1, -3, 0.7),
                                          Eigen::Vector3d(-0.4, 0.2, 0.7)}) {
    const Eigen::Vector3d p = camera_to_map * on_plane;
    EXPECT_NEAR(in_map.head<3>().dot(p) + in_map[3], 0.0, 1e-12);
  }
  // A point 0.1 above the plane in the camera frame is 0.1 above it in the map frame too.
  const Eigen::Vector3d above = camera_to_map * Eigen::Vector3d(2, 1, 0.8);
  EXPECT_NEAR(in_map.head<3>().dot(above) + in_map[3], 0.1, 1e-12);
  // Back again: the plane it started as.
  EXPECT_TRUE(ss::transformPlane(in_map, camera_to_map.inverse()).isApprox(in_camera, 1e-12));
  // A pure translation along the normal only shifts d: z = 0.7 moved up by 0.2 is z = 0.9.
  const Eigen::Vector4d lifted = ss::transformPlane(in_camera, Eigen::Isometry3d(Eigen::Translation3d(5, 6, 0.2)));
  EXPECT_TRUE(lifted.isApprox(Eigen::Vector4d(0, 0, 1, -0.9), 1e-12));
  const ss::PlaneCoefficients stored = ss::toPlaneCoefficients(2.0 * lifted);
  EXPECT_NEAR(stored.head<3>().norm(), 1.0f, 1e-6f);
  EXPECT_NEAR(stored[3], -0.9f, 1e-6f);
}
