// Preprocessing pipeline: finite points -> supporting plane -> points above it and over its
// extent -> voxel grid -> normals. Keeps the input<->voxel maps so every method reports on the input cloud.
#include "symmetry_segmentation/preprocessing.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <numeric>

#include <pcl/features/normal_3d.h>
#include <pcl/features/normal_3d_omp.h>
#include <pcl/search/kdtree.h>
#include <pcl/segmentation/extract_clusters.h>

#include "symmetry_segmentation/background_surfaces.h"
#include "symmetry_segmentation/errors.h"
#include "symmetry_segmentation/organized_normals.h"
#include "symmetry_segmentation/quantile.h"
#include "symmetry_segmentation/voxel_grid.h"

namespace symmetry_segmentation {
namespace {

// How far (pixels) from a kept pixel the table band's pixels get normals: a bottom strip a few
// pixels high under its object, with room for the noise of its edge.
constexpr int kBandPixelReach = 12;

/// The pixels of `candidates` within `reach` pixels (a square) of a pixel of `kept`, in order.
std::vector<int> pixelsNear(std::uint32_t width, std::uint32_t height, const std::vector<int>& kept,
                            const std::vector<int>& candidates, int reach) {
  const int w = static_cast<int>(width), h = static_cast<int>(height);
  // Dilation by a square as two running counts: along the rows, then along the columns.
  std::vector<int> marked(static_cast<std::size_t>(w) * h, 0), across(marked.size(), 0);
  for (int i : kept) marked[i] = 1;
  for (int y = 0; y < h; ++y) {
    int count = 0;
    for (int x = 0; x < w + reach; ++x) {
      if (x < w) count += marked[y * w + x];
      if (x - 2 * reach - 1 >= 0) count -= marked[y * w + x - 2 * reach - 1];
      if (x - reach >= 0 && x - reach < w) across[y * w + x - reach] = count > 0;
    }
  }
  std::vector<int> near;
  std::vector<int> column_count(static_cast<std::size_t>(w) * h, 0);
  for (int x = 0; x < w; ++x) {
    int count = 0;
    for (int y = 0; y < h + reach; ++y) {
      if (y < h) count += across[y * w + x];
      if (y - 2 * reach - 1 >= 0) count -= across[(y - 2 * reach - 1) * w + x];
      if (y - reach >= 0 && y - reach < h) column_count[(y - reach) * w + x] = count;
    }
  }
  for (int i : candidates) {
    if (column_count[i] > 0) near.push_back(i);
  }
  return near;
}

// Below this the table leaves slivers of itself above the cut, and they are mirror images of
// each other about any vertical plane: a symmetric "object" the cut happily joins to the real one.
constexpr float kMinTableMargin = 0.005f;
// Leaf of the coarse copy the table is found in (m); how far apart (in its voxels) the table's
// points may be and still be one table, and the points above it one group.
constexpr float kCoarseLeaf = 0.015f;
constexpr float kTableConnectVoxels = 3.0f;
constexpr float kGroupConnectVoxels = 2.0f;
// A group of points above the table with this share over the table's polygon stands on it.
constexpr float kStandingShare = 0.5f;
constexpr float kNoiseCell = 0.02f;
constexpr float kTableFacingCos = 0.8f;  // within ~37 deg of the table's normal
constexpr std::size_t kMinNoiseCellPoints = 5;
constexpr std::size_t kMinNoiseSamples = 100;
constexpr std::size_t kNoiseSamplePoints = 40000;
// A camera this high over the table looks at it; an origin lower (or under it) is no camera's.
constexpr float kMinCameraHeight = 0.2f;

bool isFinitePoint(const PointT& p) { return std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z); }

// Where normals are oriented toward: the mean sensor origin (a fused scene's cameras all look
// at the objects from above the table), else the cloud's own origin (0,0,0 for camera-frame
// clouds, the usual convention).
Eigen::Vector3f chooseViewpoint(const Scene& scene) {
  if (scene.sensor_origins.empty()) return scene.cloud->sensor_origin_.head<3>();
  Eigen::Vector3f mean = Eigen::Vector3f::Zero();
  for (const auto& origin : scene.sensor_origins) mean += origin;
  return mean / static_cast<float>(scene.sensor_origins.size());
}

// Orients the plane so that its normal points up (gravity's, where known) or the sensors (or,
// without any, most off-plane points) are on its positive side. Points on the plane are left
// out of the vote: their side is noise.
PlaneCoefficients orientPlane(PlaneCoefficients plane, const Scene& scene, const Eigen::Vector3f& viewpoint,
                              const Cloud& coarse, float on_plane_distance) {
  float side = 0.0f;
  if (scene.up) {
    side = plane.head<3>().dot(*scene.up);
  } else if (!scene.sensor_origins.empty()) {
    side = plane.head<3>().dot(viewpoint) + plane[3];
  } else {
    for (const auto& p : coarse.points) {
      const float distance = plane.head<3>().dot(p.getVector3fMap()) + plane[3];
      if (std::fabs(distance) > on_plane_distance) side += distance > 0 ? 1.f : -1.f;
    }
  }
  return side < 0.0f ? PlaneCoefficients(-plane) : plane;
}

// Fills in the normals that are missing (NaN), oriented toward the viewpoint.
void estimateMissingNormals(Cloud& cloud, const Eigen::Vector3f& viewpoint, float radius) {
  pcl::NormalEstimationOMP<PointT, pcl::Normal> estimator(2);
  auto input = cloud.makeShared();
  estimator.setInputCloud(input);
  estimator.setSearchMethod(std::make_shared<pcl::search::KdTree<PointT>>());
  estimator.setRadiusSearch(radius);
  estimator.setViewPoint(viewpoint.x(), viewpoint.y(), viewpoint.z());
  pcl::PointCloud<pcl::Normal> normals;
  estimator.compute(normals);
  for (std::size_t i = 0; i < cloud.size(); ++i) {
    if (std::isfinite(cloud.points[i].normal_x)) continue;  // keep the sensor's own normals
    cloud.points[i].normal_x = normals.points[i].normal_x;
    cloud.points[i].normal_y = normals.points[i].normal_y;
    cloud.points[i].normal_z = normals.points[i].normal_z;
    cloud.points[i].curvature = normals.points[i].curvature;
  }
}

// Which coarse voxels over the table go on: those over its polygon, and every voxel of a group
// (connected above the table) that mostly is - an object at the edge of a fused scan reaches
// past the table seen around it, while the background of a single view stands elsewhere.
std::vector<bool> voxelsOverSupport(const Cloud& coarse, const std::vector<bool>& above, const SupportPolygon& polygon,
                                    float connect_distance) {
  std::vector<bool> keep(coarse.size(), false);
  auto candidates = std::make_shared<Cloud>();
  std::vector<int> candidate_voxel;
  for (std::size_t v = 0; v < coarse.size(); ++v) {
    if (!above[v]) continue;
    candidates->push_back(coarse.points[v]);
    candidate_voxel.push_back(static_cast<int>(v));
  }
  if (candidates->empty()) return keep;
  pcl::EuclideanClusterExtraction<PointT> grouping;
  grouping.setClusterTolerance(connect_distance);
  grouping.setMinClusterSize(1);
  grouping.setSearchMethod(std::make_shared<pcl::search::KdTree<PointT>>());
  grouping.setInputCloud(candidates);
  std::vector<pcl::PointIndices> groups;
  grouping.extract(groups);
  for (const pcl::PointIndices& group : groups) {
    std::size_t over = 0;
    for (int k : group.indices) over += polygon.contains(candidates->points[k].getVector3fMap());
    const bool stands = static_cast<float>(over) >= kStandingShare * static_cast<float>(group.indices.size());
    for (int k : group.indices) {
      if (stands || polygon.contains(candidates->points[k].getVector3fMap())) keep[candidate_voxel[k]] = true;
    }
  }
  return keep;
}

// Unmarks the kept coarse voxels that lie on a wall, shelf back or floor reaching into the region.
void removeBackgroundSurfaces(const Cloud& coarse, const PlaneCoefficients& table, const PreprocessParams& params,
                              float coarse_leaf, std::vector<bool>& keep) {
  if (!(params.background_extent > 0.0f)) return;
  std::vector<bool> off_table(coarse.size());
  for (std::size_t v = 0; v < coarse.size(); ++v) {
    off_table[v] = std::fabs(table.head<3>().dot(coarse.points[v].getVector3fMap()) + table[3]) > params.ransac_distance;
  }
  BackgroundSurfaceParams surfaces;
  surfaces.ransac_distance = params.ransac_distance;
  surfaces.ransac_iterations = params.ransac_iterations;
  surfaces.connect_distance = kTableConnectVoxels * coarse_leaf;
  surfaces.max_object_extent = params.background_extent;
  const std::vector<bool> background = backgroundSurfacePoints(coarse, off_table, keep, surfaces);
  for (std::size_t v = 0; v < coarse.size(); ++v) {
    if (background[v]) keep[v] = false;
  }
}

// The sensor's noise: how the table's points spread about their own 2 cm cell's median height
// (robust sigma), so that a table that is not flat (a fused map's slow drift) does not count.
// With normals, only points facing the table's way: the objects' sides reach into its band
// (all points when too few have a normal). A cell's own median sits closer to its few points
// than the true height: with 5 points the sigma comes out about a quarter low - the safe side.
float localTableNoise(const Cloud& input, const std::vector<int>& finite, const std::vector<float>& distances,
                      const PlaneCoefficients& plane, float band, bool has_normals) {
  const Eigen::Vector3f up = plane.head<3>();
  const Eigen::Vector3f e1 = up.unitOrthogonal();
  const Eigen::Vector3f e2 = up.cross(e1);
  const auto in_band = [&](std::size_t k) { return std::fabs(distances[k]) < band; };
  std::size_t band_points = 0;
  for (std::size_t k = 0; k < distances.size(); ++k) band_points += in_band(k) ? 1 : 0;
  // Every stride-th band point: a camera frame's 2 cm cell holds some 100 pixels, a few dozen tell.
  const std::size_t stride = std::max<std::size_t>(1, band_points / kNoiseSamplePoints);
  const auto samples = [&](bool facing_only) {
    std::vector<std::pair<std::int64_t, float>> cell_heights;  // (2 cm cell, height)
    std::size_t seen = 0;
    for (std::size_t k = 0; k < finite.size(); ++k) {
      if (!in_band(k) || seen++ % stride != 0) continue;
      const PointT& point = input.points[finite[k]];
      if (facing_only && !(std::fabs(point.getNormalVector3fMap().dot(up)) >= kTableFacingCos)) continue;
      const Eigen::Vector3f p = point.getVector3fMap();
      const Eigen::Vector2f uv(e1.dot(p) / kNoiseCell, e2.dot(p) / kNoiseCell);
      if (!(uv.cwiseAbs().maxCoeff() < 1e9f)) continue;
      const auto u = static_cast<std::int64_t>(std::floor(uv.x()));
      const auto v = static_cast<std::int64_t>(std::floor(uv.y()));
      cell_heights.emplace_back(u * (std::int64_t{1} << 32) + v, distances[k]);
    }
    return cell_heights;
  };
  std::vector<std::pair<std::int64_t, float>> cell_heights = samples(has_normals);
  if (has_normals && cell_heights.size() < kMinNoiseSamples) cell_heights = samples(false);
  std::sort(cell_heights.begin(), cell_heights.end());
  std::vector<float> residuals;
  std::vector<float> cell;
  for (std::size_t first = 0; first < cell_heights.size();) {
    std::size_t last = first;
    cell.clear();
    while (last < cell_heights.size() && cell_heights[last].first == cell_heights[first].first) {
      cell.push_back(cell_heights[last++].second);
    }
    first = last;
    if (cell.size() < kMinNoiseCellPoints) continue;
    const float median = quantileOf(cell, 0.5f);
    for (float h : cell) residuals.push_back(std::fabs(h - median));
  }
  if (residuals.size() < kMinNoiseSamples) return 0.0f;
  return 1.4826f * quantileOf(residuals, 0.5f);
}

// One origin alone does not make a single view (a fused cloud may name its last camera): a
// camera's frame keeps its pixel grid or comes without normals.
bool oneCamera(const Scene& scene) {
  return scene.sensor_origins.size() == 1 && (scene.cloud->isOrganized() || !scene.has_normals);
}

// The median distance from `viewpoint` of the points within `band` of the table; 0 without any.
float medianTableRange(const Cloud& input, const std::vector<int>& finite, const std::vector<float>& distances,
                       const Eigen::Vector3f& viewpoint, float band) {
  std::vector<float> ranges;
  for (std::size_t k = 0; k < finite.size(); ++k) {
    if (std::fabs(distances[k]) < band) ranges.push_back((input.points[finite[k]].getVector3fMap() - viewpoint).norm());
  }
  return ranges.empty() ? 0.0f : quantileOf(ranges, 0.5f);
}

float marginFor(const std::optional<TableSpread>& spread, const PreprocessParams& params) {
  if (!spread) return params.table_margin;  // too few table points to tell
  // Not std::clamp: a configured margin under kMinTableMargin is the cap, as documented.
  return std::min(std::max(spread->median + 3.0f * spread->sigma, kMinTableMargin), params.table_margin);
}

}  // namespace

std::optional<TableSpread> tableSpread(const std::vector<float>& distances, const PreprocessParams& params) {
  // The table's own points are the bulk of those within ransac_distance of the plane; their
  // spread (median absolute deviation, scaled to a Gaussian sigma) is the sensor's noise there.
  std::vector<float> near;
  for (float d : distances) {
    if (std::fabs(d) < params.ransac_distance) near.push_back(d);
  }
  if (near.size() < 100) return std::nullopt;  // too few table points to tell
  const auto middle = near.begin() + static_cast<std::ptrdiff_t>(near.size() / 2);
  std::nth_element(near.begin(), middle, near.end());
  TableSpread spread;
  spread.median = *middle;
  for (float& d : near) d = std::fabs(d - spread.median);
  std::nth_element(near.begin(), middle, near.end());
  spread.sigma = 1.4826f * *middle;
  return spread;
}

float adaptiveTableMargin(const std::vector<float>& distances, const PreprocessParams& params) {
  return marginFor(tableSpread(distances, params), params);
}

PreprocessedScene preprocess(const Scene& scene, const PreprocessParams& params) {
  if (!scene.cloud || scene.cloud->empty()) throw InputError(scene.cloud_path, "cloud has zero points");
  if (!(params.voxel_size > 0.0f)) throw InputError("preprocessing.voxel_size must be positive");
  const Cloud& input = *scene.cloud;
  PreprocessedScene out;

  std::vector<int> finite;
  finite.reserve(input.size());
  for (std::size_t i = 0; i < input.size(); ++i) {
    if (isFinitePoint(input.points[i])) finite.push_back(static_cast<int>(i));
  }
  if (finite.empty()) throw InputError(scene.cloud_path, "cloud has no finite points");
  out.viewpoint = chooseViewpoint(scene);
  // A camera frame without normals gets them from its pixel grid, the table band's too.
  const bool organized_normals = !scene.has_normals && params.organized_normal_smoothing > 0.0f && input.isOrganized();
  if (params.max_range > 0.0f) {
    std::vector<int> in_range;
    for (int i : finite) {
      if ((input.points[i].getVector3fMap() - out.viewpoint).norm() <= params.max_range) in_range.push_back(i);
    }
    out.dropped.out_of_range = finite.size() - in_range.size();
    finite.swap(in_range);
  }

  if (params.remove_table) {
    PlaneCoefficients plane;
    // With the cloud's normals (fused clouds), which way each surface faces helps tell the table.
    const float coarse_leaf = std::max(params.voxel_size, kCoarseLeaf);
    const VoxelGridResult coarse_grid = voxelDownsample(input, finite, coarse_leaf, scene.has_normals);
    const auto& coarse = coarse_grid.cloud;
    bool found = false;
    if (scene.table_plane) {
      plane = *scene.table_plane;
      found = true;
    } else {
      // The sensor is known from the scene's origins or the cloud's own viewpoint (a PCD's VIEWPOINT).
      std::optional<Eigen::Vector3f> sensor;
      if (!scene.sensor_origins.empty()) sensor = out.viewpoint;
      found = estimateSupportingPlane(*coarse, params, sensor, plane, oneCamera(scene), scene.up);
    }
    if (found) {
      out.has_table = true;
      out.table_plane = orientPlane(plane, scene, out.viewpoint, *coarse, params.ransac_distance);
      // The plane through the table's own cells, and heights over its curved top: the same table
      // whichever plane found it, and a cut that follows it where it drifts or bends.
      if (params.table_surface_cell > 0.0f) {
        auto surface = TableSurface::fit(input, finite, out.table_plane, params.ransac_distance, scene.has_normals,
                                         params.table_surface_cell);
        if (surface) {
          out.table_plane = surface->plane();
          out.table_surface = TableSurface::fit(input, finite, out.table_plane, params.ransac_distance,
                                                scene.has_normals, params.table_surface_cell);
        }
      }
      std::vector<float> distances(finite.size());
      for (std::size_t k = 0; k < finite.size(); ++k) {
        distances[k] = out.tableHeight(input.points[finite[k]].getVector3fMap());
      }
      // The margin from the spread about the plane, bends included: a far table's noise grows
      // with the range, and the near table's scatter about its surface alone would leave the far
      // table's specks above the cut.
      std::vector<float> plane_distances(finite.size());
      for (std::size_t k = 0; k < finite.size(); ++k) {
        plane_distances[k] = out.table_plane.head<3>().dot(input.points[finite[k]].getVector3fMap()) + out.table_plane[3];
      }
      const std::optional<TableSpread> spread = tableSpread(plane_distances, params);
      out.table_noise =
          localTableNoise(input, finite, distances, out.table_plane, params.ransac_distance, scene.has_normals);
      out.table_margin = params.adaptive_table_margin ? marginFor(spread, params) : params.table_margin;
      // Only a camera over the table: a cloud saved in a world frame may name an origin elsewhere.
      const bool camera_over_table =
          oneCamera(scene) && out.table_plane.head<3>().dot(out.viewpoint) + out.table_plane[3] > kMinCameraHeight;
      out.table_range =
          camera_over_table ? medianTableRange(input, finite, distances, out.viewpoint, params.ransac_distance) : 0.0f;
      const float max_height = params.max_object_height > 0.0f ? params.max_object_height
                                                                : std::numeric_limits<float>::infinity();
      // The table's extent: only what stands over it goes on (walls, floor, background do not).
      std::vector<bool> input_over_support;
      if (params.crop_to_support) {
        out.support_polygon = SupportPolygon::fromPlanePoints(*coarse, out.table_plane, params.ransac_distance,
                                                              kTableConnectVoxels * coarse_leaf, params.support_margin);
      }
      if (out.support_polygon) {
        std::vector<bool> coarse_above(coarse->size());
        for (std::size_t v = 0; v < coarse->size(); ++v) {
          const float height = out.tableHeight(coarse->points[v].getVector3fMap());
          coarse_above[v] = height > out.table_margin && height <= max_height;
        }
        std::vector<bool> keep =
            voxelsOverSupport(*coarse, coarse_above, *out.support_polygon, kGroupConnectVoxels * coarse_leaf);
        removeBackgroundSurfaces(*coarse, out.table_plane, params, coarse_leaf, keep);
        // A voxel straddling the margin is no group's: its points go by the polygon alone.
        input_over_support.assign(input.size(), false);
        for (std::size_t v = 0; v < keep.size(); ++v) {
          for (int i : coarse_grid.members[v]) {
            input_over_support[i] = coarse_above[v] ? keep[v] : out.support_polygon->contains(input.points[i].getVector3fMap());
          }
        }
      }
      std::vector<int> above;
      above.reserve(finite.size());
      for (std::size_t k = 0; k < finite.size(); ++k) {
        if (distances[k] <= out.table_margin) {
          if (organized_normals && distances[k] >= -out.table_margin) out.table_band.push_back(finite[k]);
          ++out.dropped.on_table;
        } else if (distances[k] > max_height) {
          ++out.dropped.too_high;
        } else if (!input_over_support.empty() && !input_over_support[finite[k]]) {
          ++out.dropped.off_support;
        } else {
          above.push_back(finite[k]);
        }
      }
      finite.swap(above);
    }
  }
  const std::size_t before_roi = finite.size();
  finite.erase(std::remove_if(finite.begin(), finite.end(),
                              [&](int i) { return !scene.inRegionOfInterest(input.points[i].getVector3fMap()); }),
               finite.end());
  out.dropped.outside_roi = before_roi - finite.size();
  if (finite.empty()) {
    throw InputError(scene.cloud_path, scene.region_of_interest
                                           ? "no points left inside the region of interest above the supporting plane "
                                             "(over its extent, below max_object_height)"
                                           : "no points left above the supporting plane (over its extent, below "
                                             "max_object_height)");
  }
  out.kept_input_indices = finite;

  // A camera frame without normals gets them from its pixel grid, at the sensor's resolution;
  // the voxels average them.
  // The table band's too, in the same pass, for object_bottoms: the band pixels near a kept
  // pixel (an object's bottom lies under its object in the image; the rest is the table).
  Cloud::Ptr kept_with_normals;
  if (organized_normals) {
    out.table_band = pixelsNear(input.width, input.height, finite, out.table_band, kBandPixelReach);
    std::vector<int> kept_and_band = finite;
    kept_and_band.insert(kept_and_band.end(), out.table_band.begin(), out.table_band.end());
    kept_with_normals =
        pointsWithOrganizedNormals(input, kept_and_band, out.viewpoint, params.organized_normal_smoothing);
  }
  if (kept_with_normals) {
    for (std::size_t k = finite.size(); k < kept_with_normals->size(); ++k) {
      out.table_band_normals.push_back(kept_with_normals->points[k].getNormalVector3fMap());
    }
    kept_with_normals->resize(finite.size());
  } else {
    out.table_band.clear();
  }
  VoxelGridResult grid;
  if (kept_with_normals) {
    std::vector<int> all(finite.size());
    std::iota(all.begin(), all.end(), 0);
    grid = voxelDownsample(*kept_with_normals, all, params.voxel_size, true);
    for (auto& members : grid.members) {
      for (int& member : members) member = finite[member];  // back to input points
    }
  } else {
    grid = voxelDownsample(input, finite, params.voxel_size, scene.has_normals);
  }
  out.cloud = grid.cloud;
  out.voxel_to_input = std::move(grid.members);
  out.input_to_voxel.assign(input.size(), -1);
  for (std::size_t v = 0; v < out.voxel_to_input.size(); ++v) {
    for (int i : out.voxel_to_input[v]) out.input_to_voxel[i] = static_cast<int>(v);
  }

  std::size_t missing_normals = 0;
  for (const auto& p : out.cloud->points) {
    if (!std::isfinite(p.normal_x)) ++missing_normals;
  }
  if (missing_normals > 0) {
    estimateMissingNormals(*out.cloud, out.viewpoint, params.normal_radius);
    // Isolated voxels get no estimate: face them toward the sensor rather than leave NaN.
    for (auto& p : out.cloud->points) {
      if (std::isfinite(p.normal_x) && std::isfinite(p.normal_y) && std::isfinite(p.normal_z)) continue;
      Eigen::Vector3f toward = out.viewpoint - p.getVector3fMap();
      if (toward.norm() < 1e-6f) toward = Eigen::Vector3f::UnitZ();
      toward.normalize();
      p.normal_x = toward.x();
      p.normal_y = toward.y();
      p.normal_z = toward.z();
    }
  }
  return out;
}

std::optional<SupportSurface> supportSurface(const PreprocessedScene& scene) {
  if (!scene.has_table) return std::nullopt;
  SupportSurface support;
  support.plane = scene.table_plane;
  support.noise = scene.table_noise;
  if (scene.support_polygon) support.polygon = scene.support_polygon->corners();
  return support;
}

std::vector<int> expandToInput(const PreprocessedScene& scene, const std::vector<int>& voxel_indices) {
  std::vector<int> result;
  for (int v : voxel_indices) {
    const auto& members = scene.voxel_to_input.at(v);
    result.insert(result.end(), members.begin(), members.end());
  }
  std::sort(result.begin(), result.end());
  result.erase(std::unique(result.begin(), result.end()), result.end());
  return result;
}

}  // namespace symmetry_segmentation
