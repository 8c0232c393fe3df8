#include "symmetry_segmentation/ros/octomap_message.h"

namespace symmetry_segmentation {

// Exactly what genmsg produces for octomap_msgs/Octomap (its MD5 is computed from this text).
const char* const kOctomapDefinition =
    "# A 3D map in binary format, as Octree\n"
    "Header header\n"
    "\n"
    "# Flag to denote a binary (only free/occupied) or full occupancy octree (.bt/.ot file)\n"
    "bool binary\n"
    "\n"
    "# Class id of the contained octree \n"
    "string id\n"
    "\n"
    "# Resolution (in m) of the smallest octree nodes\n"
    "float64 resolution\n"
    "\n"
    "# binary serialization of octree, use conversions.h to read and write octrees\n"
    "int8[] data\n"
    "\n"
    "================================================================================\n"
    "MSG: std_msgs/Header\n"
    "# Standard metadata for higher-level stamped data types.\n"
    "# This is generally used to communicate timestamped data \n"
    "# in a particular coordinate frame.\n"
    "# \n"
    "# sequence ID: consecutively increasing ID \n"
    "uint32 seq\n"
    "#Two-integer timestamp that is expressed as:\n"
    "# * stamp.sec: seconds (stamp_secs) since epoch (in Python the variable is called 'secs')\n"
    "# * stamp.nsec: nanoseconds since stamp_secs (in Python the variable is called 'nsecs')\n"
    "# time-handling sugar is provided by the client library\n"
    "time stamp\n"
    "#Frame this data is associated with\n"
    "string frame_id\n";

}  // namespace symmetry_segmentation
