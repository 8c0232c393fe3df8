// The per-surface PCA the upright stage's proposals share.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include <Eigen/Eigenvalues>

#include "symmetry_segmentation/symmetry/surface_shapes.h"

namespace ss = symmetry_segmentation;

namespace {

void addPoint(ss::Cloud& cloud, std::vector<int>& labels, const Eigen::Vector3f& p, const Eigen::Vector3f& normal,
              int label) {
  ss::PointT point;
  point.getVector3fMap() = p;
  point.getNormalVector3fMap() = normal;
  cloud.push_back(point);
  labels.push_back(label);
}

}  // namespace

TEST(SurfaceShapes, AFlatFaceAndAHalfCylinderByLabel) {
  ss::Cloud cloud;
  std::vector<int> labels;
  // Label 3: a 10 x 6 cm horizontal face at z = 0.2, normals up.
  for (int i = 0; i <= 10; ++i) {
    for (int j = 0; j <= 6; ++j) addPoint(cloud, labels, {0.01f * i, 0.01f * j, 0.2f}, Eigen::Vector3f::UnitZ(), 3);
  }
  // Label 1: half a cylinder of radius 5 cm about the vertical through (1, 0), normals outward;
  // interleaved with unlabelled points, which belong to no surface.
  for (int k = 0; k <= 18; ++k) {
    const float a = static_cast<float>(M_PI) * k / 18.0f;
    for (int h = 0; h < 5; ++h) {
      const Eigen::Vector3f radial(std::cos(a), std::sin(a), 0.0f);
      addPoint(cloud, labels, Eigen::Vector3f(1.0f, 0.0f, 0.02f * h) + 0.05f * radial, radial, 1);
      addPoint(cloud, labels, {5.0f, 5.0f, 5.0f}, Eigen::Vector3f::UnitZ(), 0);
    }
  }
  const std::vector<ss::SurfaceShape> shapes = ss::surfaceShapes(cloud, labels);
  ASSERT_EQ(shapes.size(), 2u);  // labels 1 and 3, in that order; 2 and 0 are no surface

  const ss::SurfaceShape& half_cylinder = shapes[0];
  EXPECT_EQ(half_cylinder.points.size(), 19u * 5u);
  EXPECT_TRUE(std::is_sorted(half_cylinder.points.begin(), half_cylinder.points.end()));
  EXPECT_GT(half_cylinder.curvature, 0.05f);
  EXPECT_LT(half_cylinder.mean_normal.norm(), 0.8f);  // normals spread over half a turn
  EXPECT_NEAR(half_cylinder.centroid.z(), 0.04f, 1e-4f);

  const ss::SurfaceShape& face = shapes[1];
  EXPECT_EQ(face.points.size(), 11u * 7u);
  EXPECT_NEAR(face.centroid.x(), 0.05f, 1e-4f);
  EXPECT_NEAR(face.centroid.y(), 0.03f, 1e-4f);
  EXPECT_NEAR(face.centroid.z(), 0.2f, 1e-4f);
  EXPECT_LT(face.curvature, 1e-6f);
  EXPECT_NEAR(std::fabs(face.face_normal.z()), 1.0f, 1e-4f);
  EXPECT_NEAR(face.mean_normal.norm(), 1.0f, 1e-5f);
  // The scatter's largest direction runs along the face's 10 cm side.
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3f> pca(face.scatter);
  EXPECT_NEAR(std::fabs(pca.eigenvectors().col(2).x()), 1.0f, 1e-4f);
}

TEST(SurfaceShapes, LabelsThatDoNotMatchTheCloudGiveNone) {
  ss::Cloud cloud;
  std::vector<int> labels;
  addPoint(cloud, labels, Eigen::Vector3f::Zero(), Eigen::Vector3f::UnitZ(), 1);
  labels.push_back(1);
  EXPECT_TRUE(ss::surfaceShapes(cloud, labels).empty());
  EXPECT_TRUE(ss::surfaceShapes(ss::Cloud(), {}).empty());
}
