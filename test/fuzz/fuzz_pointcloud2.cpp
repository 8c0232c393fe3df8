// Fuzz target: sensor_msgs/PointCloud2 through sceneFromCloudMessage.
// Input layout (little-endian): u32 height, u32 width, u32 point_step, u32 row_step,
// u8 is_bigendian, u8 field count (mod 17), per field {u8 name (index into kNames),
// u32 offset, u8 datatype, u32 count}, then the data bytes.
#include <pcl/console/print.h>

#include "fuzz_support.h"
#include "symmetry_segmentation/errors.h"
#include "symmetry_segmentation/ros/cloud_conversion.h"

namespace ss = symmetry_segmentation;

namespace {
const char* const kNames[] = {"x",      "y",   "z",    "normal_x",  "normal_y",  "normal_z", "rgb",
                              "rgba",   "curvature", "intensity", "",        "label",    "X"};
}

// PCL warns on stderr about every field it cannot map; millions of lines slow the fuzzer down.
extern "C" int LLVMFuzzerInitialize(int*, char***) {
  pcl::console::setVerbosityLevel(pcl::console::L_ALWAYS);
  return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  fuzz_support::ByteReader in(data, size);
  sensor_msgs::PointCloud2 message;
  message.header.frame_id = "fuzz";
  message.height = in.u32();
  message.width = in.u32();
  message.point_step = in.u32();
  message.row_step = in.u32();
  message.is_bigendian = in.u8() & 1;
  const int fields = in.u8() % 17;
  for (int i = 0; i < fields; ++i) {
    sensor_msgs::PointField field;
    field.name = kNames[in.u8() % (sizeof(kNames) / sizeof(kNames[0]))];
    field.offset = in.u32();
    field.datatype = in.u8();
    field.count = in.u32();
    message.fields.push_back(field);
  }
  const std::string bytes = in.rest();
  message.data.assign(bytes.begin(), bytes.end());
  message.is_dense = false;
  ss::Scene scene;
  try {
    scene = ss::sceneFromCloudMessage(message);
  } catch (const ss::InputError&) {
    return 0;
  }
  // Message order is kept: one point per (row, column).
  FUZZ_CHECK(scene.cloud);
  FUZZ_CHECK(scene.cloud->size() == static_cast<std::size_t>(message.width) * message.height);
  return 0;
}
