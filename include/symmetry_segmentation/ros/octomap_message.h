#pragma once
// A wire-compatible stand-in for octomap_msgs/Octomap (not packaged in Debian): same data type
// string, full definition text and MD5, so octomap_server's topics and bags interoperate. Header
// traits are declared, so tf2_ros::MessageFilter and message_filters accept it.

#include <cstdint>
#include <string>
#include <vector>

#include <boost/shared_ptr.hpp>
#include <ros/message_traits.h>
#include <ros/serialization.h>
#include <std_msgs/Header.h>

namespace symmetry_segmentation {

struct OctomapMessage {
  std_msgs::Header header;
  bool binary = false;        ///< Occupied/free only (.bt) or full node data (.ot).
  std::string id;             ///< Tree class, e.g. "OcTree", "ColorOcTree".
  double resolution = 0.0;    ///< Leaf size (m).
  std::vector<int8_t> data;   ///< The tree's own (binary or full) serialisation.

  using Ptr = boost::shared_ptr<OctomapMessage>;
  using ConstPtr = boost::shared_ptr<const OctomapMessage>;
};

constexpr const char* kOctomapDataType = "octomap_msgs/Octomap";
constexpr const char* kOctomapMd5 = "9a45536b45c5e409cd49f04bb2d9999f";
extern const char* const kOctomapDefinition;

}  // namespace symmetry_segmentation

namespace ros {
namespace message_traits {

template <>
struct IsMessage<symmetry_segmentation::OctomapMessage> : TrueType {};
template <>
struct IsMessage<const symmetry_segmentation::OctomapMessage> : TrueType {};
template <>
struct HasHeader<symmetry_segmentation::OctomapMessage> : TrueType {};
template <>
struct HasHeader<const symmetry_segmentation::OctomapMessage> : TrueType {};

template <>
struct MD5Sum<symmetry_segmentation::OctomapMessage> {
  static const char* value() { return symmetry_segmentation::kOctomapMd5; }
  static const char* value(const symmetry_segmentation::OctomapMessage&) { return value(); }
  static const uint64_t static_value1 = 0x9a45536b45c5e409ULL;
  static const uint64_t static_value2 = 0xcd49f04bb2d9999fULL;
};

template <>
struct DataType<symmetry_segmentation::OctomapMessage> {
  static const char* value() { return symmetry_segmentation::kOctomapDataType; }
  static const char* value(const symmetry_segmentation::OctomapMessage&) { return value(); }
};

template <>
struct Definition<symmetry_segmentation::OctomapMessage> {
  static const char* value() { return symmetry_segmentation::kOctomapDefinition; }
  static const char* value(const symmetry_segmentation::OctomapMessage&) { return value(); }
};

}  // namespace message_traits

namespace serialization {

template <>
struct Serializer<symmetry_segmentation::OctomapMessage> {
  template <typename Stream, typename T>
  inline static void allInOne(Stream& stream, T m) {
    stream.next(m.header);
    stream.next(m.binary);
    stream.next(m.id);
    stream.next(m.resolution);
    stream.next(m.data);
  }
  ROS_DECLARE_ALLINONE_SERIALIZER
};

}  // namespace serialization
}  // namespace ros
