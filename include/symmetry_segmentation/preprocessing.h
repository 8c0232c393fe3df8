#pragma once
// Scene preprocessing shared by every method: supporting plane (from the scene or RANSAC),
// removal of points on or below it, voxel-grid downsampling with a map back to the input
// points, the table's extent (only points over it go on), and normals (a file's own normals are kept as given, averaged per voxel; missing
// ones are estimated and oriented toward the sensor).

#include <optional>
#include <vector>

#include "symmetry_segmentation/parameter_schema.h"
#include "symmetry_segmentation/scene.h"
#include "symmetry_segmentation/segmentation_result.h"
#include "symmetry_segmentation/support_polygon.h"
#include "symmetry_segmentation/table_surface.h"

namespace symmetry_segmentation {

struct PreprocessParams {
  float voxel_size = 0.01f;
  bool remove_table = true;
  float table_margin = 0.015f;
  bool adaptive_table_margin = true;
  float ransac_distance = 0.01f;
  int ransac_iterations = 500;
  float normal_radius = 0.03f;
  float organized_normal_smoothing = 10.0f;
  float max_range = 0.0f;
  bool crop_to_support = true;
  float support_margin = 0.05f;
  float max_object_height = 0.5f;
  float background_extent = 0.5f;
  float max_support_tilt = 30.0f;
  float table_surface_cell = 0.02f;
};

inline void describeParameters(ParameterList<PreprocessParams>& list) {
  using P = PreprocessParams;
  list.add("voxel_size", &P::voxel_size, 0.003, 0.05, "m", "voxel-grid leaf size of the working cloud").live()
      .add("remove_table", &P::remove_table, "find the supporting plane (table_plane.txt or RANSAC) and drop it")
      .add("table_margin", &P::table_margin, 0.0, 0.1, "m",
           "points closer than this above the plane count as table (with adaptive_table_margin: the largest margin)")
      .add("adaptive_table_margin", &P::adaptive_table_margin,
           "margin = 3 sigma of the table points' noise (5 mm .. table_margin), so fused clouds keep object bottoms")
      .add("ransac_distance", &P::ransac_distance, 0.001, 0.1, "m", "RANSAC inlier distance when the plane is estimated")
      .add("ransac_iterations", &P::ransac_iterations, 1, 1000000, "", "RANSAC iterations when the plane is estimated")
      .add("normal_radius", &P::normal_radius, 0.005, 0.5, "m", "radius for normal estimation when the cloud has none")
      .add("organized_normal_smoothing", &P::organized_normal_smoothing, 0.0, 100.0, "pixels",
           "a camera frame without normals (organized) gets them from its pixel grid, over a window this many "
           "pixels wide, before the voxel grid; 0: estimate them on the working cloud within normal_radius instead")
      .add("max_range", &P::max_range, 0.0, 100.0, "m", "drop points farther than this from the sensor; 0 keeps all")
      .add("crop_to_support", &P::crop_to_support,
           "keep only points over the table's extent (the polygon of its points): walls, floor, background go")
      .add("support_margin", &P::support_margin, 0.0, 1.0, "m",
           "the table's polygon grows by this, for objects at its edge whose footprint hides the table there")
      .add("max_object_height", &P::max_object_height, 0.0, 10.0, "m",
           "points higher than this above the table are not on a tabletop object; 0: no limit")
      .add("background_extent", &P::background_extent, 0.0, 100.0, "m",
           "a flat patch wider than this that reaches past the table's extent is background (a wall, a shelf "
           "back, the floor), not an object; 0: keep it")
      .add("max_support_tilt", &P::max_support_tilt, 0.0, 90.0, "deg",
           "with gravity known (scene up, node ~up_frame), the supporting plane's normal is within this angle of up")
      .add("table_surface_cell", &P::table_surface_cell, 0.0, 0.2, "m",
           "heights are measured from the table's top fitted as a gently curved surface to the median heights of "
           "its points in cells this wide (a fused map's drift, a far table bending away), and the plane used is "
           "the one through those cells, whether table_plane.txt or RANSAC found the table; 0: the plane as found");
}

/// The band over the table, in table margins, where the table's cut and noise leave an object's
/// foot uncertain: an object whose top stands lower is thin (a book, a board), one whose box ends
/// lower rests on the table and reaches down to it.
constexpr float kTableBandMargins = 2.0f;

struct PreprocessedScene {
  Cloud::Ptr cloud;                        ///< Downsampled object points with normals.
  std::vector<int> input_to_voxel;         ///< Per input point: index into `cloud`, or -1 if dropped.
  std::vector<std::vector<int>> voxel_to_input;  ///< Per downsampled point: its input points.
  std::vector<int> kept_input_indices;     ///< Input points that survived (finite, above the table).
  bool has_table = false;
  float table_margin = 0.0f;               ///< The margin actually used (m).
  float table_noise = 0.0f;                ///< The sensor's noise (m): robust sigma of the table's points about
                                           ///< their 2 cm cell's median height; 0: unknown.
  /// One camera's view from over the table (20 cm or more): the median distance of the table's
  /// points from it (m), where its depth noise is table_noise (a camera's grows with the square
  /// of the distance); 0 otherwise.
  float table_range = 0.0f;
  PlaneCoefficients table_plane = PlaneCoefficients::Zero();  ///< Normal points away from the table top.
  /// The table's top as a curved surface over table_plane, when one was fitted (table_surface_cell).
  std::optional<TableSurface> table_surface;
  /// Signed height of `p` over the table's top: over table_surface when fitted, else over table_plane.
  float tableHeight(const Eigen::Vector3f& p) const { return tableTopHeight(table_plane, table_surface, p); }
  TableTop tableTop() const { return TableTop(table_plane, table_surface); }
  std::optional<SupportPolygon> support_polygon;  ///< The table's extent, when cropped to it.
  Eigen::Vector3f viewpoint = Eigen::Vector3f::Zero();         ///< Used to orient normals.
  /// A camera frame without normals gets them from its pixel grid, the points dropped within
  /// the table margin too (an object's bottom among them): those points (sorted input indices)
  /// and their normals (NaN where the grid gives none). Empty otherwise.
  std::vector<int> table_band;
  std::vector<Eigen::Vector3f> table_band_normals;
  /// Finite input points left out, by reason (checked in this order): why an object is missing.
  struct Dropped {
    std::size_t out_of_range = 0;  ///< Farther than max_range from the viewpoint.
    std::size_t on_table = 0;      ///< Within the table margin, or under the table.
    std::size_t too_high = 0;      ///< Higher than max_object_height above it.
    std::size_t off_support = 0;   ///< Not over the table's extent, or a background surface.
    std::size_t outside_roi = 0;   ///< Outside the region of interest.
  } dropped;
};

/// Throws InputError when nothing is left to segment (no finite point, all on the table).
PreprocessedScene preprocess(const Scene& scene, const PreprocessParams& params);

/// How the table's points spread about its plane, from these signed point-to-plane distances: the
/// median and robust sigma (scaled median absolute deviation) of those within ransac_distance;
/// nullopt when fewer than 100 are.
struct TableSpread {
  float median = 0.0f;
  float sigma = 0.0f;
};
std::optional<TableSpread> tableSpread(const std::vector<float>& distances, const PreprocessParams& params);

/// The margin above the table for these signed point-to-plane distances: median + 3 sigma of
/// tableSpread, clamped to [5 mm, params.table_margin]; params.table_margin when not measured.
float adaptiveTableMargin(const std::vector<float>& distances, const PreprocessParams& params);

/// Estimates the supporting plane of `cloud` with RANSAC; returns false if none is found. Of up to
/// three large planes (a single view may show more wall or floor than table), the one with the
/// most other points standing over it within 0.3 m, on the `viewpoint` side (without one: on
/// the side most points are on). `single_view`: the cloud was seen from `viewpoint` alone.
/// With `up` (gravity) known only planes within params.max_support_tilt of it are candidates,
/// and false is returned when there is none.
bool estimateSupportingPlane(const Cloud& cloud, const PreprocessParams& params,
                             const std::optional<Eigen::Vector3f>& viewpoint, PlaneCoefficients& plane,
                             bool single_view = false, const std::optional<Eigen::Vector3f>& up = std::nullopt);

/// The supporting surface as methods report it (plane and, when cropped to it, its polygon).
std::optional<SupportSurface> supportSurface(const PreprocessedScene& scene);

/// Expands per-downsampled-point indices to the input points they represent (sorted).
std::vector<int> expandToInput(const PreprocessedScene& scene, const std::vector<int>& voxel_indices);

}  // namespace symmetry_segmentation
