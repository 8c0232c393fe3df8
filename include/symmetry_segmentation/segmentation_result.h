#pragma once
// What every method returns: segments as indices into the input cloud (file order).

#include <optional>
#include <string>
#include <utility>
#include <vector>

#include <Eigen/Core>
#include <Eigen/Geometry>

namespace symmetry_segmentation {

struct SymmetryPlane {
  Eigen::Vector3f normal = Eigen::Vector3f::UnitX();  ///< Unit normal.
  float distance = 0.0f;                              ///< Plane: normal . x + distance = 0.
};

struct SegmentScores {
  float occlusion = 0.0f;
  float smoothness = 0.0f;
};

/// A box around an object's points (object_box.h says how it is oriented).
struct ObjectBox {
  Eigen::Vector3f center = Eigen::Vector3f::Zero();
  Eigen::Matrix3f axes = Eigen::Matrix3f::Identity();  ///< Columns: the box's unit x, y, z (right-handed).
  Eigen::Vector3f size = Eigen::Vector3f::Zero();      ///< Full edge lengths along x, y, z (m).
};

/// An object completed by its symmetry (stage completion).
struct SegmentCompletion {
  std::vector<Eigen::Vector3f> points;  ///< Its unseen side: reflections (and turned copies) into
                                        ///< unobserved space, sides carried down to the support.
  ObjectBox box;                        ///< Around the visible and the added points, and down to
                                        ///< the support when the object rests on it.
  Eigen::Vector3f frame_position = Eigen::Vector3f::Zero();  ///< Symmetry frame: origin on the plane,
  Eigen::Quaternionf frame_orientation = Eigen::Quaternionf::Identity();  ///< x its normal, z up.
};

struct Segment {
  std::vector<int> indices;  ///< Sorted indices into the input cloud.
  std::optional<SymmetryPlane> symmetry;
  std::optional<SegmentScores> scores;
  std::optional<ObjectBox> box;  ///< In the input cloud's frame (addObjectBoxes).
  std::optional<SegmentCompletion> completion;  ///< In the input cloud's frame.
};

/// The surface the objects stand on: only points over its polygon were segmented.
struct SupportSurface {
  Eigen::Vector4f plane = Eigen::Vector4f::Zero();  ///< a x + b y + c z + d = 0, normal pointing up.
  std::vector<Eigen::Vector3f> polygon;              ///< Corners in order, on the plane; empty: not cropped.
  float noise = 0.0f;  ///< The sensor's noise there (m; PreprocessedScene::table_noise); 0: unknown.
};

/// Stage name and wall time in milliseconds, in execution order; "total" last.
using Timings = std::vector<std::pair<std::string, double>>;

/// Named counts a method reports about its run (e.g. hypotheses, segments before filtering).
using Counts = std::vector<std::pair<std::string, std::size_t>>;

struct SegmentationResult {
  std::size_t input_points = 0;
  std::optional<SupportSurface> support;
  std::vector<Segment> segments;
  Timings timing_ms;
  Counts counts;
};

}  // namespace symmetry_segmentation
