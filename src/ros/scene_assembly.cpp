#include "symmetry_segmentation/ros/scene_assembly.h"

#include "symmetry_segmentation/SegmentCloud.h"
#include "symmetry_segmentation/depth_image_occupancy.h"
#include "symmetry_segmentation/errors.h"
#include "symmetry_segmentation/point_validity.h"
#include "symmetry_segmentation/ros/cloud_conversion.h"

namespace symmetry_segmentation {

Scene assembleScene(const sensor_msgs::PointCloud2& cloud, const SceneInputs& inputs) {
  using Response = SegmentCloud::Response;
  Scene scene;
  try {
    scene = sceneFromCloudMessage(cloud);
    if (!inputs.cloud_to_processing.matrix().isIdentity(0.0)) {
      transformCloud(*scene.cloud, inputs.cloud_to_processing, scene.has_normals);
    }
    if (inputs.region_of_interest) {
      scene.region_of_interest = regionOfInterest(inputs.region_of_interest->min, inputs.region_of_interest->max);
    }
  } catch (const InputError& error) {
    throw RequestError(Response::INVALID_INPUT, error.what());
  }
  // One walk: the segmentable points' bounds also size a map ray-cast for this cloud.
  Eigen::AlignedBox3d segmentable;
  for (const auto& p : scene.cloud->points) {
    if (isUsablePoint(p) && scene.inRegionOfInterest(p.getVector3fMap())) {
      segmentable.extend(p.getVector3fMap().cast<double>());
    }
  }
  if (segmentable.isEmpty()) {
    throw RequestError(Response::INVALID_INPUT,
                       inputs.region_of_interest ? "no finite point inside the region of interest"
                                                 : "cloud has no finite point");
  }
  // The sensor origin is passed on even with a map: the core orients normals and the table
  // plane toward it (without one it votes, which a large table patch can get wrong).
  if (inputs.sensor_origin) {
    scene.sensor_origins.push_back(*inputs.sensor_origin);
  } else if (!inputs.occupancy && !inputs.occupancy_for_region) {
    // A camera's organized cloud (openni2, realsense2) needs neither a sensor frame nor a map:
    // the camera is fitted to its pixels, and its depth image is the occupancy.
    if (const auto camera = cameraCenterOfFrame(*scene.cloud)) scene.sensor_origins.push_back(*camera);
  }
  scene.table_plane = inputs.table_plane;
  scene.up = inputs.up;
  if (inputs.occupancy) {
    scene.occupancy = inputs.occupancy;
  } else if (inputs.occupancy_for_region) {
    const Eigen::Vector3d margin = Eigen::Vector3d::Constant(kMapMargin);
    try {
      scene.occupancy =
          inputs.occupancy_for_region(Eigen::AlignedBox3d(segmentable.min() - margin, segmentable.max() + margin));
    } catch (const InputError& error) {
      throw RequestError(Response::INVALID_INPUT, error.what());
    }
  }
  if (!scene.occupancy && scene.sensor_origins.empty()) {
    throw RequestError(Response::NO_OCCUPANCY,
                       "no OctoMap received, and no sensor frame or cloud viewpoint to ray-cast one from");
  }
  return scene;
}

}  // namespace symmetry_segmentation
