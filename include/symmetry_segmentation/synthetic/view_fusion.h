#pragma once
// Fusing the rendered views into one labelled cloud with normals, and into an OctoMap.

#include <memory>
#include <vector>

#include "symmetry_segmentation/scene.h"
#include "symmetry_segmentation/synthetic/random.h"
#include "symmetry_segmentation/synthetic/virtual_camera.h"

namespace symmetry_segmentation {
namespace synthetic {

struct FusionOptions {
  double voxel_size = 0.003;          ///< Edge of the averaging voxels (m).
  double normal_noise_sigma = 0.03;   ///< Per-component noise added to averaged true normals.
};

struct FusedCloud {
  Cloud::Ptr cloud;
  std::vector<int> labels;  ///< One per cloud point.
};

/// Voxel average of all views' points, standing in for a registered multi-view fusion.
/// Points are binned by where their ray truly met the surface, so depth noise does not
/// thicken the surface into several voxel layers; the output position is the mean of the
/// noisy measurements (residual noise ~ sigma / sqrt(n)). Each voxel yields one point per
/// object label and per surface side (normals agreeing with the first point's), so touching
/// objects and the two sides of a thin wall stay apart. Normals are the averaged true normals
/// with a little seeded noise, standing in for the error of estimated normals. Output order:
/// sorted by voxel, so it is deterministic.
FusedCloud fuseViews(const std::vector<RenderedView>& views, const FusionOptions& options, Random& random);

/// OctoMap built by inserting each view's points as rays from that view's camera origin.
std::shared_ptr<octomap::OcTree> buildOccupancy(const std::vector<RenderedView>& views, double resolution,
                                                double max_range);

}  // namespace synthetic
}  // namespace symmetry_segmentation
