#pragma once
// Ground truth of a labelled scene, from either source the evaluation reads:
// - a scene directory's labels.txt (the generator's: 0 = not an object, k > 0 = object k);
// - the "label" field of an OSD / mOSD frame (Richtsfeld et al., PCD as distributed): 0 = invalid
//   point, 1-9 = parts of the supporting table, 10-19 unused, 20-29 = pieces of the first object,
//   30-39 = the second, ... At object level an object is label / 10; at part level each label of
//   20 or more is its own object (mOSD labels the disjoint visible pieces of an occluded object
//   apart, and a method that sees only geometry cannot join them).
// Optionally the points near the table are left out of the evaluation (kIgnoredLabel): whether
// the bottom centimetre of an object belongs to it or to the table is not decided the same way
// by annotators and methods.

#include <cstdint>
#include <string>
#include <vector>

#include "symmetry_segmentation/scene.h"

namespace symmetry_segmentation {

/// How to read a scene's ground truth.
struct GroundTruthOptions {
  bool osd_parts = false;  ///< OSD frames: each visible piece is an object (else: whole objects).
  /// When > 0 (m): points within this distance of the table plane are ignored in objects and
  /// segments alike. The plane is fitted to the table-labelled points of an OSD frame, else the
  /// scene's table_plane.txt; a scene with neither is an InputError.
  double table_band = 0.0;
};

/// Ground truth from an OSD label field (see above): 0 = not an object, else the object's label.
std::vector<int> osdGroundTruth(const std::vector<std::uint32_t>& file_labels, bool parts);

/// The OSD category of a frame named learnN or testN (the data set's README: boxes, stacked,
/// occluded, cylindric, mixed, complex); empty for other names.
std::string osdCategory(const std::string& scene_name);

/// Sets the labels of points within `band` of `plane` (and not NaN) to kIgnoredLabel.
void ignoreNearPlane(const Cloud& cloud, const PlaneCoefficients& plane, double band, std::vector<int>& labels);

/// The least-squares plane of the finite points whose OSD label is 1-9, after dropping points
/// farther than 2 cm from a RANSAC fit (annotators' stray table pixels on object borders).
/// Throws InputError when there are fewer than 3 such points.
PlaneCoefficients fitOsdTablePlane(const std::string& source, const Cloud& cloud,
                                   const std::vector<std::uint32_t>& file_labels);

/// loadScene(path) with its ground truth in `labels`: labels.txt when the scene has one, else the
/// cloud's OSD label field (kind = osdCategory(name) unless scene_info.yaml gave one), then the
/// table band. Leaves labels empty when the scene has neither source.
Scene loadLabelledScene(const std::string& path, const GroundTruthOptions& options);

}  // namespace symmetry_segmentation
