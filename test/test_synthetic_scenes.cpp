// Whole generated scenes: every kind, determinism, and the ground-truth properties each kind
// promises (occluded object in pieces, objects standing on others, free/occupied/unknown space).

#include <gtest/gtest.h>

#include <algorithm>
#include <cstring>
#include <map>
#include <optional>
#include <sstream>

#include <octomap/OcTree.h>
#include <pcl/kdtree/kdtree_flann.h>
#include <pcl/search/kdtree.h>
#include <pcl/segmentation/extract_clusters.h>

#include "symmetry_segmentation/errors.h"
#include "symmetry_segmentation/synthetic/scene_generator.h"

namespace ss = symmetry_segmentation;
using namespace symmetry_segmentation::synthetic;

namespace {

/// Generated scenes are cached: each (kind, seed) is built once per test binary.
const GeneratedScene& sceneFor(SceneKind kind, uint32_t seed = 1) {
  static std::map<std::pair<SceneKind, uint32_t>, GeneratedScene> cache;
  auto key = std::make_pair(kind, seed);
  auto it = cache.find(key);
  if (it == cache.end()) {
    GeneratorOptions options;
    options.kind = kind;
    options.seed = seed;
    it = cache.emplace(key, generate(options)).first;
  }
  return it->second;
}

pcl::PointCloud<pcl::PointXYZ>::Ptr pointsWithLabel(const ss::Scene& scene, int label) {
  pcl::PointCloud<pcl::PointXYZ>::Ptr points(new pcl::PointCloud<pcl::PointXYZ>);
  for (std::size_t i = 0; i < scene.size(); ++i) {
    if (scene.labels[i] != label) continue;
    const auto& p = scene.cloud->points[i];
    points->push_back(pcl::PointXYZ(p.x, p.y, p.z));
  }
  return points;
}

std::vector<pcl::PointIndices> euclideanClusters(const pcl::PointCloud<pcl::PointXYZ>::Ptr& points,
                                                 double tolerance, int min_size) {
  pcl::search::KdTree<pcl::PointXYZ>::Ptr tree(new pcl::search::KdTree<pcl::PointXYZ>);
  pcl::EuclideanClusterExtraction<pcl::PointXYZ> extraction;
  extraction.setClusterTolerance(tolerance);
  extraction.setMinClusterSize(min_size);
  extraction.setSearchMethod(tree);
  extraction.setInputCloud(points);
  std::vector<pcl::PointIndices> clusters;
  extraction.extract(clusters);
  return clusters;
}

/// Smallest distance between points of two labels.
double labelDistance(const ss::Scene& scene, int a, int b) {
  const auto points_a = pointsWithLabel(scene, a);
  const auto points_b = pointsWithLabel(scene, b);
  pcl::KdTreeFLANN<pcl::PointXYZ> tree;
  tree.setInputCloud(points_a);
  double best = 1e9;
  std::vector<int> index(1);
  std::vector<float> squared(1);
  for (const auto& p : points_b->points) {
    if (tree.nearestKSearch(p, 1, index, squared) == 1) best = std::min(best, std::sqrt(double(squared[0])));
  }
  return best;
}

bool insideConvex(const Footprint& polygon, const Eigen::Vector2d& p) {
  for (std::size_t i = 0; i < polygon.size(); ++i) {
    const Eigen::Vector2d edge = polygon[(i + 1) % polygon.size()] - polygon[i];
    const Eigen::Vector2d to_p = p - polygon[i];
    if (edge.x() * to_p.y() - edge.y() * to_p.x() < 0.0) return false;  // right of a CCW edge
  }
  return true;
}

std::string serialized(const octomap::OcTree& tree) {
  std::stringstream stream;
  tree.writeBinaryConst(stream);
  return stream.str();
}

bool sameClouds(const ss::Cloud& a, const ss::Cloud& b) {
  if (a.size() != b.size()) return false;
  for (std::size_t i = 0; i < a.size(); ++i) {
    const auto& p = a.points[i];
    const auto& q = b.points[i];
    if (std::memcmp(p.data, q.data, sizeof(p.data)) != 0 || std::memcmp(p.data_n, q.data_n, sizeof(p.data_n)) != 0 ||
        p.rgba != q.rgba) {
      return false;
    }
  }
  return true;
}

class EveryKind : public ::testing::TestWithParam<SceneKind> {};

}  // namespace

TEST_P(EveryKind, HasItsObjectsLabelledInTheCloud) {
  const SceneKind kind = GetParam();
  const GeneratedScene& generated = sceneFor(kind);
  const ss::Scene& scene = generated.scene;
  const int objects = static_cast<int>(generated.layout.world.objects.size());
  const std::map<SceneKind, std::pair<int, int>> expected_objects = {
      {SceneKind::Isolated, {3, 5}},  {SceneKind::Touching, {7, 7}},  {SceneKind::Stacked, {5, 5}},
      {SceneKind::Occluded, {4, 4}},  {SceneKind::NonConvex, {4, 5}}, {SceneKind::Clutter, {8, 12}}};
  EXPECT_GE(objects, expected_objects.at(kind).first);
  EXPECT_LE(objects, expected_objects.at(kind).second);

  EXPECT_EQ(scene.kind, toString(kind));
  EXPECT_EQ(scene.name, toString(kind) + "_seed1");
  EXPECT_TRUE(scene.has_normals);
  EXPECT_TRUE(scene.has_color);
  ASSERT_TRUE(scene.table_plane);
  EXPECT_TRUE(scene.table_plane->isApprox(ss::PlaneCoefficients(0, 0, 1, 0)));
  EXPECT_EQ(scene.sensor_origins.size(), 4u);
  ASSERT_TRUE(scene.occupancy);
  ASSERT_EQ(scene.labels.size(), scene.size());
  EXPECT_GT(scene.size(), 50000u);
  EXPECT_LT(scene.size(), 250000u);

  std::vector<int> counts(objects + 1, 0);
  for (int label : scene.labels) {
    ASSERT_GE(label, 0);
    ASSERT_LE(label, objects);
    ++counts[label];
  }
  EXPECT_GT(counts[0], 20000) << "table";
  for (int label = 1; label <= objects; ++label) {
    EXPECT_GT(counts[label], 300) << "object " << label << " ("
                                  << toString(generated.layout.world.objects[label - 1].shape) << ")";
  }
  std::size_t facing_a_camera = 0;
  for (const auto& p : scene.cloud->points) {
    ASSERT_TRUE(std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z));
    // Normals point to the free side, so toward at least one of the cameras that saw the point.
    const Eigen::Vector3f normal(p.normal_x, p.normal_y, p.normal_z);
    bool faces = false;
    for (const auto& origin : scene.sensor_origins) faces = faces || normal.dot(origin - p.getVector3fMap()) > 0.0f;
    facing_a_camera += faces ? 1 : 0;
    ASSERT_NEAR(Eigen::Vector3f(p.normal_x, p.normal_y, p.normal_z).norm(), 1.0f, 1e-4f);
    ASSERT_GT(p.z, -0.05f);  // nothing below the table top but its own thickness
  }
  EXPECT_GT(facing_a_camera, scene.size() * 998 / 1000);
}

TEST_P(EveryKind, ObjectsDoNotInterpenetrate) {
  const GeneratedScene& generated = sceneFor(GetParam());
  const auto& objects = generated.layout.world.objects;
  const auto& stacked = generated.layout.stacked;
  for (std::size_t i = 0; i < objects.size(); ++i) {
    for (std::size_t j = i + 1; j < objects.size(); ++j) {
      const int a = objects[i].label;
      const int b = objects[j].label;
      const bool is_stack = std::count(stacked.begin(), stacked.end(), std::make_pair(a, b)) +
                                std::count(stacked.begin(), stacked.end(), std::make_pair(b, a)) >
                            0;
      if (is_stack) continue;  // overlapping footprints at different heights
      EXPECT_GE(separation(objects[i].worldFootprint(), objects[j].worldFootprint()), -1e-6)
          << "objects " << a << " and " << b;
    }
  }
}

INSTANTIATE_TEST_SUITE_P(SyntheticScenes, EveryKind, ::testing::ValuesIn(allSceneKinds()),
                         [](const ::testing::TestParamInfo<SceneKind>& info) { return toString(info.param); });

TEST(SyntheticScenes, SameSeedSameSceneOtherSeedOtherScene) {
  GeneratorOptions options;
  options.kind = SceneKind::Clutter;
  options.seed = 1;
  const GeneratedScene again = generate(options);
  const ss::Scene& first = sceneFor(SceneKind::Clutter, 1).scene;
  EXPECT_TRUE(sameClouds(*first.cloud, *again.scene.cloud));
  EXPECT_EQ(first.labels, again.scene.labels);
  EXPECT_EQ(serialized(*first.occupancy), serialized(*again.scene.occupancy));
  ASSERT_EQ(first.sensor_origins.size(), again.scene.sensor_origins.size());
  for (std::size_t i = 0; i < first.sensor_origins.size(); ++i) {
    EXPECT_EQ(first.sensor_origins[i], again.scene.sensor_origins[i]);
  }

  options.seed = 2;
  options.build_occupancy = false;
  const ss::Scene other = generateScene(options);
  EXPECT_FALSE(sameClouds(*first.cloud, *other.cloud));
  EXPECT_FALSE(other.occupancy);
}

TEST(SyntheticScenes, OccludedObjectFallsApartIntoPieces) {
  for (uint32_t seed : {1u, 2u}) {
    const GeneratedScene& generated = sceneFor(SceneKind::Occluded, seed);
    const int occluded = generated.layout.occluded_label;
    ASSERT_GT(occluded, 0);
    const auto points = pointsWithLabel(generated.scene, occluded);
    const auto pieces = euclideanClusters(points, 0.015, 100);
    EXPECT_GE(pieces.size(), 2u) << "seed " << seed << ": " << points->size() << " points";
    // The pieces hold nearly all of the object's points: it is split, not just sparse.
    std::size_t in_pieces = 0;
    for (const auto& piece : pieces) in_pieces += piece.indices.size();
    EXPECT_GT(in_pieces, points->size() * 9 / 10);
  }
}

TEST(SyntheticScenes, StackedObjectsStandOnOthers) {
  const GeneratedScene& generated = sceneFor(SceneKind::Stacked);
  const auto& objects = generated.layout.world.objects;
  ASSERT_GE(generated.layout.stacked.size(), 2u);
  for (const auto& [upper, lower] : generated.layout.stacked) {
    const SyntheticObject& top = objects[upper - 1];
    const SyntheticObject& bottom = objects[lower - 1];
    EXPECT_NEAR(top.position().z(), bottom.worldTop(), 1e-9);
    // In the cloud: the upper object's lowest points are at the lower object's top, above it.
    const auto upper_points = pointsWithLabel(generated.scene, upper);
    const auto lower_points = pointsWithLabel(generated.scene, lower);
    ASSERT_FALSE(upper_points->empty());
    ASSERT_FALSE(lower_points->empty());
    float upper_min_z = 1e9f, lower_max_z = -1e9f;
    Eigen::Vector2f upper_centre = Eigen::Vector2f::Zero();
    for (const auto& p : upper_points->points) {
      upper_min_z = std::min(upper_min_z, p.z);
      upper_centre += Eigen::Vector2f(p.x, p.y) / upper_points->size();
    }
    for (const auto& p : lower_points->points) lower_max_z = std::max(lower_max_z, p.z);
    EXPECT_NEAR(upper_min_z, bottom.worldTop(), 0.01);
    EXPECT_NEAR(lower_max_z, bottom.worldTop(), 0.01);
    EXPECT_GT(upper_min_z, 0.03f);  // clearly off the table
    EXPECT_TRUE(insideConvex(bottom.worldFootprint(), upper_centre.cast<double>()))
        << "upper object centred over lower";
  }
  // The same-footprint box pair: the two surfaces really meet.
  const auto& [upper, lower] = generated.layout.stacked.front();
  EXPECT_LT(labelDistance(generated.scene, upper, lower), 0.006);
}

TEST(SyntheticScenes, TouchingObjectsMeet) {
  const GeneratedScene& generated = sceneFor(SceneKind::Touching);
  // Objects 1-3 are a flush row of boxes, 4-5 a box and a cylinder, 6-7 two round objects.
  for (auto [a, b] : {std::make_pair(1, 2), std::make_pair(2, 3), std::make_pair(4, 5), std::make_pair(6, 7)}) {
    EXPECT_LT(labelDistance(generated.scene, a, b), 0.01) << a << "-" << b;
    EXPECT_NEAR(separation(generated.layout.world.objects[a - 1].worldFootprint(),
                           generated.layout.world.objects[b - 1].worldFootprint()),
                0.0, 1e-3)
        << a << "-" << b;
  }
}

TEST(SyntheticScenes, OctomapKnowsFreeOccupiedAndUnknownSpace) {
  const GeneratedScene& generated = sceneFor(SceneKind::Stacked);
  const octomap::OcTree& tree = *generated.scene.occupancy;
  EXPECT_NEAR(tree.getResolution(), 0.01, 1e-12);
  // A camera ray that meets the lower box of the first stack (the upper box may hide the
  // box's middle from some cameras, so try a few heights).
  const SyntheticObject& box = generated.layout.world.objects[generated.layout.stacked.front().second - 1];
  const Eigen::Vector3d centre = box.position() + Eigen::Vector3d(0, 0, box.height() / 2);
  std::optional<WorldHit> hit;
  Eigen::Vector3d camera;
  Ray ray;
  for (const auto& pose : generated.cameras) {
    for (double fraction : {0.5, 0.3, 0.15}) {
      camera = pose.origin();
      const Eigen::Vector3d target = box.position() + Eigen::Vector3d(0, 0, fraction * box.height());
      ray = Ray{camera, (target - camera).normalized()};
      hit = rayIntersect(generated.layout.world, ray, 0.0, 10.0);
      if (hit && hit->label == box.label) break;
    }
    if (hit && hit->label == box.label) break;
  }
  ASSERT_TRUE(hit);
  ASSERT_EQ(hit->label, box.label) << "the lower box should be in view of some camera";

  auto node = [&](const Eigen::Vector3d& p) { return tree.search(p.x(), p.y(), p.z()); };
  // Between the camera and the surface: free.
  for (double fraction : {0.3, 0.6, 0.9}) {
    const auto* free_node = node(camera + fraction * (hit->point - camera));
    ASSERT_NE(free_node, nullptr) << fraction;
    EXPECT_FALSE(tree.isNodeOccupied(free_node)) << fraction;
  }
  // At the surface: occupied (allowing a voxel for noise and discretisation).
  bool occupied = false;
  for (double s = -0.012; s <= 0.012; s += 0.002) {
    const auto* surface_node = node(hit->point + s * ray.direction);
    occupied = occupied || (surface_node && tree.isNodeOccupied(surface_node));
  }
  EXPECT_TRUE(occupied);
  // Inside / behind the box: never observed.
  EXPECT_EQ(node(centre), nullptr);
  EXPECT_EQ(node(Eigen::Vector3d(box.position().x(), box.position().y(), -0.1)), nullptr);  // under the table
}

TEST(SyntheticScenes, BadOptionsAreRejected) {
  GeneratorOptions options;
  options.num_views = 0;
  EXPECT_THROW(generateScene(options), ss::InputError);
  options = GeneratorOptions{};
  options.voxel_size = -1.0;
  EXPECT_THROW(generateScene(options), ss::InputError);
  EXPECT_THROW(parseSceneKind("pile"), ss::InputError);
  for (SceneKind kind : allSceneKinds()) EXPECT_EQ(parseSceneKind(toString(kind)), kind);
}
