// Stage upright of the symmetry method: vertical planes proposed from single surfaces.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "symmetry_segmentation/symmetry/symmetry_plane.h"
#include "symmetry_segmentation/symmetry/upright_hypotheses.h"
#include "fake_evidence.h"
#include "test_clouds.h"

namespace ss = symmetry_segmentation;

namespace {

const Eigen::Vector3f kUp = Eigen::Vector3f::UnitZ();

/// Evidence without a map: a reflection within 1 cm of a point lands on it, else nothing is known.
test_support::FakeEvidence landing(const ss::Cloud& cloud) {
  test_support::FakeEvidence evidence(cloud);
  evidence.landOnNearestWithin(0.01f);
  return evidence;
}

ss::PointT point(const Eigen::Vector3f& p, const Eigen::Vector3f& n) {
  ss::PointT q;
  q.getVector3fMap() = p;
  q.getNormalVector3fMap() = n;
  return q;
}

/// Side of a vertical cylinder seen over [from, to] radians, as `strips` surfaces (labels
/// first_label, first_label + 1, ...), the way supervoxel merging often splits a can.
void addCylinderSide(ss::Cloud& cloud, std::vector<int>& labels, const Eigen::Vector3f& axis, float radius,
                     float height, float from, float to, int strips, int first_label) {
  const int columns = static_cast<int>((to - from) * radius / 0.008f);
  for (int c = 0; c <= columns; ++c) {
    const float angle = from + (to - from) * static_cast<float>(c) / static_cast<float>(columns);
    const Eigen::Vector3f normal(std::cos(angle), std::sin(angle), 0.0f);
    const int strip = std::min(strips - 1, c * strips / (columns + 1));
    for (float z = 0.005f; z < height; z += 0.008f) {
      cloud.push_back(point(axis + radius * normal + Eigen::Vector3f(0, 0, z), normal));
      labels.push_back(first_label + strip);
    }
  }
}

bool hasPlane(const std::vector<ss::SymmetryHypothesis>& hypotheses, const Eigen::Vector3f& normal,
              const Eigen::Vector3f& through, float angle_deg, float distance) {
  ss::SymmetryPlane truth;
  truth.normal = normal.normalized();
  truth.distance = -truth.normal.dot(through);
  return std::any_of(hypotheses.begin(), hypotheses.end(), [&](const ss::SymmetryHypothesis& h) {
    return ss::planeAngleDeg(h.plane, truth) < angle_deg && ss::planeDistanceDifference(h.plane, truth) < distance;
  });
}

float distanceToPlane(const ss::SymmetryPlane& plane, const Eigen::Vector3f& p) {
  return std::fabs(ss::signedDistance(plane, p));
}

}  // namespace

TEST(UprightHypotheses, CylinderStripsProposeThePlaneBisectingWhatWasSeen) {
  // A can seen over 200 degrees centred on +y, split into two surfaces: each strip alone
  // would bisect itself; the plane must go through the axis and bisect the whole seen arc.
  ss::Cloud cloud;
  std::vector<int> labels;
  const Eigen::Vector3f axis(0.2f, -0.1f, 0.0f);
  const float centre = static_cast<float>(M_PI) / 2.0f;
  const float half = 100.0f * static_cast<float>(M_PI) / 180.0f;
  addCylinderSide(cloud, labels, axis, 0.04f, 0.15f, centre - half, centre + half, 2, 1);

  const auto hypotheses = ss::uprightHypotheses(landing(cloud), ss::surfaceShapes(cloud, labels), kUp, ss::UprightHypothesisParams{});
  ASSERT_FALSE(hypotheses.empty());
  bool through_axis = false;
  for (const auto& h : hypotheses) {
    EXPECT_LT(std::fabs(h.plane.normal.dot(kUp)), 1e-4f) << "every proposal is vertical";
    through_axis = through_axis || distanceToPlane(h.plane, axis) < 0.003f;
  }
  EXPECT_TRUE(through_axis);
  // The seen arc is symmetric about the plane x = axis.x (normal along x).
  EXPECT_TRUE(hasPlane(hypotheses, Eigen::Vector3f::UnitX(), axis, 8.0f, 0.003f));
}

TEST(UprightHypotheses, AMugsHandleOrientsThePlaneThroughItsAxis) {
  // A mug seen over 200 degrees centred on -y, its handle sticking out 3 cm at -40 degrees: the
  // plane through the axis must contain the handle, not bisect the seen arc (mirrored there the
  // handle lands in free space). Space within 2 cm of the wall is not known to be free, so only
  // the handle's outer half contradicts a wrong plane, and it lies beyond the 1.2-radius column.
  ss::Cloud cloud;
  std::vector<int> labels;
  const Eigen::Vector3f axis(0.1f, 0.2f, 0.0f);
  const float radius = 0.04f;
  const float centre = -static_cast<float>(M_PI) / 2.0f;
  const float half = 100.0f * static_cast<float>(M_PI) / 180.0f;
  addCylinderSide(cloud, labels, axis, radius, 0.1f, centre - half, centre + half, 1, 1);
  const float handle_angle = -40.0f * static_cast<float>(M_PI) / 180.0f;
  const Eigen::Vector3f out(std::cos(handle_angle), std::sin(handle_angle), 0.0f);
  const Eigen::Vector3f across = kUp.cross(out);
  for (float r = radius + 0.005f; r <= radius + 0.03f; r += 0.005f) {
    for (float z = 0.02f; z <= 0.08f; z += 0.005f) {
      cloud.push_back(point(axis + r * out + Eigen::Vector3f(0, 0, z), -across));
      labels.push_back(2);
    }
  }
  auto evidence = landing(cloud);
  evidence.free_landing = [&](const Eigen::Vector3f& p) {
    return Eigen::Vector2f(p.x() - axis.x(), p.y() - axis.y()).norm() > radius + 0.02f;
  };
  const auto planeThroughAxis = [&](const ss::UprightHypothesisParams& params) {
    const auto hypotheses = ss::uprightHypotheses(evidence, ss::surfaceShapes(cloud, labels), kUp, params);
    const auto through = std::find_if(hypotheses.begin(), hypotheses.end(), [&](const ss::SymmetryHypothesis& h) {
      return !h.anchor.empty() && distanceToPlane(h.plane, axis) < 0.003f;
    });
    EXPECT_NE(through, hypotheses.end());
    return through == hypotheses.end() ? ss::SymmetryPlane{} : through->plane;
  };
  const ss::SymmetryPlane handle_plane{across, -across.dot(axis)};
  EXPECT_LT(ss::planeAngleDeg(planeThroughAxis(ss::UprightHypothesisParams{}), handle_plane), 8.0f);

  ss::UprightHypothesisParams column_only;
  column_only.attached_reach = 1.2f;  // the handle's outer half is not scored
  EXPECT_GT(ss::planeAngleDeg(planeThroughAxis(column_only), handle_plane), 20.0f)
      << "the handle orients the plane even without its outer half (else this test shows nothing)";
}

TEST(UprightHypotheses, AHandleFittedAsAThinCylinderOfItsOwnStillOrientsTheMugsPlane) {
  // A real handle's front is curved: it gets a thin upright axis of its own. Its points must
  // still count with the mug's column (a part held against its side, not a round neighbour
  // whose side is its own business), else nothing contradicts the bisector of the seen arc.
  ss::Cloud cloud;
  std::vector<int> labels;
  const Eigen::Vector3f axis(0.1f, 0.2f, 0.0f);
  const float radius = 0.04f;
  const float pi = static_cast<float>(M_PI);
  addCylinderSide(cloud, labels, axis, radius, 0.1f, -pi / 2.0f - 1.75f, -pi / 2.0f + 1.75f, 1, 1);
  const float handle_angle = -40.0f * pi / 180.0f;
  const Eigen::Vector3f out(std::cos(handle_angle), std::sin(handle_angle), 0.0f);
  const Eigen::Vector3f across = kUp.cross(out);
  const float handle_radius = 0.012f;
  const Eigen::Vector3f handle_axis = axis + (radius + 0.018f) * out;
  for (float a = -pi; a <= 0.0f; a += 0.25f) {  // its half facing the camera (-y)
    const Eigen::Vector3f normal(std::cos(a), std::sin(a), 0.0f);
    for (float z = 0.02f; z <= 0.08f; z += 0.005f) {
      cloud.push_back(point(handle_axis + handle_radius * normal + Eigen::Vector3f(0, 0, z), normal));
      labels.push_back(2);
    }
  }
  auto evidence = landing(cloud);
  evidence.free_landing = [&](const Eigen::Vector3f& p) {
    return Eigen::Vector2f(p.x() - axis.x(), p.y() - axis.y()).norm() > radius + 0.02f;
  };
  const auto hypotheses = ss::uprightHypotheses(evidence, ss::surfaceShapes(cloud, labels), kUp, ss::UprightHypothesisParams{});
  ASSERT_TRUE(std::any_of(hypotheses.begin(), hypotheses.end(), [&](const ss::SymmetryHypothesis& h) {
    return !h.anchor.empty() && distanceToPlane(h.plane, handle_axis) < 0.003f && labels[h.anchor.front()] == 2;
  })) << "the handle has no axis of its own (else this test shows nothing)";
  const ss::SymmetryPlane handle_plane{across, -across.dot(axis)};
  EXPECT_TRUE(std::any_of(hypotheses.begin(), hypotheses.end(), [&](const ss::SymmetryHypothesis& h) {
    return !h.anchor.empty() && labels[h.anchor.front()] == 1 && ss::planeAngleDeg(h.plane, handle_plane) < 8.0f &&
           distanceToPlane(h.plane, axis) < 0.003f;
  })) << "no plane through the mug's axis contains its handle";
}

TEST(UprightHypotheses, TwoTouchingCansMergedIntoOneSurfaceProposeAPlaneThroughEachAxis) {
  // Their sides meet with equal normals and supervoxel merging makes one surface of both. Each
  // can gets a plane through its own axis, anchored on its own side, and not the plane through
  // both axes (under which each would drag the other into its cut).
  ss::Cloud cloud;
  std::vector<int> labels;
  const Eigen::Vector3f left(0.0f, 0.0f, 0.0f), right(0.09f, 0.0f, 0.0f);  // radii 0.04 and 0.05
  const float pi = static_cast<float>(M_PI);
  addCylinderSide(cloud, labels, left, 0.04f, 0.12f, -pi, 0.0f, 1, 1);     // the front halves,
  addCylinderSide(cloud, labels, right, 0.05f, 0.12f, -pi, 0.0f, 1, 1);    // seen from -y
  const auto hypotheses = ss::uprightHypotheses(landing(cloud), ss::surfaceShapes(cloud, labels), kUp, ss::UprightHypothesisParams{});
  for (const Eigen::Vector3f& axis : {left, right}) {
    const auto through = std::find_if(hypotheses.begin(), hypotheses.end(), [&](const ss::SymmetryHypothesis& h) {
      return distanceToPlane(h.plane, axis) < 0.004f && !h.anchor.empty();
    });
    ASSERT_NE(through, hypotheses.end()) << "no anchored plane through the axis at x=" << axis.x();
    EXPECT_GT(ss::planeAngleDeg(through->plane, ss::SymmetryPlane{Eigen::Vector3f::UnitY(), 0.0f}), 30.0f)
        << "the plane through both axes";
    // Most anchor points lie on this can's side.
    int own = 0;
    for (int i : through->anchor) {
      const Eigen::Vector3f offset = cloud[i].getVector3fMap() - axis;
      own += std::fabs(Eigen::Vector2f(offset.x(), offset.y()).norm() - (axis.x() > 0 ? 0.05f : 0.04f)) < 0.005f;
    }
    EXPECT_GT(own, static_cast<int>(0.8 * through->anchor.size()));
  }
}

TEST(UprightHypotheses, BoxFacesProposeTheirBisectors) {
  ss::Cloud cloud;
  test_clouds::addBox(cloud, Eigen::Vector3f(0.1f, 0.2f, 0.0f), Eigen::Vector3f(0.12f, 0.08f, 0.1f), 0.008f);
  // One surface per face, told apart by normal.
  std::vector<int> labels;
  for (const auto& p : cloud.points) {
    const Eigen::Vector3f n = p.getNormalVector3fMap();
    int label = 1;
    for (const Eigen::Vector3f& axis : {Eigen::Vector3f::UnitX(), Eigen::Vector3f::UnitY(), Eigen::Vector3f::UnitZ()}) {
      if (n.dot(axis) > 0.9f) break;
      ++label;
      if (n.dot(axis) < -0.9f) break;
      ++label;
    }
    labels.push_back(label);
  }
  const auto hypotheses = ss::uprightHypotheses(landing(cloud), ss::surfaceShapes(cloud, labels), kUp, ss::UprightHypothesisParams{});
  const Eigen::Vector3f centre(0.16f, 0.24f, 0.05f);
  EXPECT_TRUE(hasPlane(hypotheses, Eigen::Vector3f::UnitX(), centre, 2.0f, 0.005f));
  EXPECT_TRUE(hasPlane(hypotheses, Eigen::Vector3f::UnitY(), centre, 2.0f, 0.005f));
  for (const auto& h : hypotheses) EXPECT_LT(std::fabs(h.plane.normal.dot(kUp)), 1e-4f);
}

TEST(UprightHypotheses, SmallSurfacesAndUnlabelledPointsProposeNothing) {
  ss::Cloud cloud;
  std::vector<int> labels;
  addCylinderSide(cloud, labels, Eigen::Vector3f::Zero(), 0.04f, 0.15f, 0.0f, 3.0f, 1, 1);
  std::vector<int> unlabelled(labels.size(), 0);
  EXPECT_TRUE(ss::uprightHypotheses(landing(cloud), ss::surfaceShapes(cloud, unlabelled), kUp, ss::UprightHypothesisParams{}).empty());
  ss::UprightHypothesisParams strict;
  strict.min_surface_points = static_cast<int>(cloud.size()) + 1;
  EXPECT_TRUE(ss::uprightHypotheses(landing(cloud), ss::surfaceShapes(cloud, labels), kUp, strict).empty());
  const ss::Cloud empty;
  EXPECT_TRUE(ss::uprightHypotheses(landing(empty), {}, kUp, ss::UprightHypothesisParams{}).empty());
}

TEST(UprightHypotheses, ASurfaceWhoseNormalsMeetNoCommonAxisProposesNoAxisPlane) {
  // A saddle-like ruled surface: normals turn but their horizontal lines do not meet.
  ss::Cloud cloud;
  std::vector<int> labels;
  for (float s = -0.06f; s <= 0.06f; s += 0.006f) {
    for (float z = 0.0f; z < 0.1f; z += 0.006f) {
      const float twist = 8.0f * (z - 0.05f);  // normal turns with height, not around an axis
      const Eigen::Vector3f n(std::cos(twist), std::sin(twist), 0.0f);
      const Eigen::Vector3f along(-n.y(), n.x(), 0.0f);
      cloud.push_back(point(Eigen::Vector3f(0.0f, 0.0f, z) + s * along, n));
      labels.push_back(1);
    }
  }
  ss::UprightHypothesisParams params;
  params.flat_curvature = 0.0f;  // only the axis test may propose
  EXPECT_TRUE(ss::uprightHypotheses(landing(cloud), ss::surfaceShapes(cloud, labels), kUp, params).empty());
}

TEST(UprightHypotheses, AppendDistinctSkipsNearEqualPlanes) {
  auto make = [](const Eigen::Vector3f& n, float d) {
    ss::SymmetryHypothesis h;
    h.plane.normal = n.normalized();
    h.plane.distance = d;
    return h;
  };
  std::vector<ss::SymmetryHypothesis> base = {make(Eigen::Vector3f::UnitX(), 0.1f)};
  const std::vector<ss::SymmetryHypothesis> extra = {
      make(Eigen::Vector3f(1.0f, 0.02f, 0.0f), 0.105f),  // ~1 degree, 5 mm: the same plane
      make(-Eigen::Vector3f::UnitX(), -0.1f),            // the same plane, flipped
      make(Eigen::Vector3f::UnitX(), 0.2f),              // parallel, 10 cm away
      make(Eigen::Vector3f::UnitY(), 0.1f)};
  ss::appendDistinctHypotheses(base, extra, 6.0f, 0.015f);
  ASSERT_EQ(base.size(), 3u);
  EXPECT_FLOAT_EQ(base[1].plane.distance, 0.2f);
  EXPECT_EQ(base[2].plane.normal, Eigen::Vector3f::UnitY());
}
