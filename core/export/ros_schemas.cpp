#include "core/export/ros_schemas.h"

namespace ydscope {
namespace {

// Field lists as in the ROS 2 (rolling) .msg files; comments left out.
#define YDSCOPE_MSG_SEPARATOR "================================================================================\n"

// Every message here starts with a std_msgs/Header, so they share its dependency block.
#define YDSCOPE_HEADER_DEPENDENCIES                                                                                    \
  YDSCOPE_MSG_SEPARATOR "MSG: std_msgs/Header\nbuiltin_interfaces/Time stamp\nstring frame_id\n" YDSCOPE_MSG_SEPARATOR \
                        "MSG: builtin_interfaces/Time\nint32 sec\nuint32 nanosec\n"

const RosSchema kLaserScan{"sensor_msgs/msg/LaserScan",
                           "std_msgs/Header header\n"
                           "float32 angle_min\n"
                           "float32 angle_max\n"
                           "float32 angle_increment\n"
                           "float32 time_increment\n"
                           "float32 scan_time\n"
                           "float32 range_min\n"
                           "float32 range_max\n"
                           "float32[] ranges\n"
                           "float32[] intensities\n" YDSCOPE_HEADER_DEPENDENCIES};

const RosSchema kPointCloud2{"sensor_msgs/msg/PointCloud2",
                             "std_msgs/Header header\n"
                             "uint32 height\n"
                             "uint32 width\n"
                             "PointField[] fields\n"
                             "bool is_bigendian\n"
                             "uint32 point_step\n"
                             "uint32 row_step\n"
                             "uint8[] data\n"
                             "bool is_dense\n" YDSCOPE_HEADER_DEPENDENCIES YDSCOPE_MSG_SEPARATOR
                             "MSG: sensor_msgs/PointField\n"
                             "uint8 INT8=1\n"
                             "uint8 UINT8=2\n"
                             "uint8 INT16=3\n"
                             "uint8 UINT16=4\n"
                             "uint8 INT32=5\n"
                             "uint8 UINT32=6\n"
                             "uint8 FLOAT32=7\n"
                             "uint8 FLOAT64=8\n"
                             "string name\n"
                             "uint32 offset\n"
                             "uint8 datatype\n"
                             "uint32 count\n"};

const RosSchema kDiagnosticArray{"diagnostic_msgs/msg/DiagnosticArray",
                                 "std_msgs/Header header\n"
                                 "DiagnosticStatus[] status\n" YDSCOPE_HEADER_DEPENDENCIES YDSCOPE_MSG_SEPARATOR
                                 "MSG: diagnostic_msgs/DiagnosticStatus\n"
                                 "byte OK=0\n"
                                 "byte WARN=1\n"
                                 "byte ERROR=2\n"
                                 "byte STALE=3\n"
                                 "byte level\n"
                                 "string name\n"
                                 "string message\n"
                                 "string hardware_id\n"
                                 "KeyValue[] values\n" YDSCOPE_MSG_SEPARATOR
                                 "MSG: diagnostic_msgs/KeyValue\n"
                                 "string key\n"
                                 "string value\n"};

const RosSchema kUInt8MultiArray{"std_msgs/msg/UInt8MultiArray",
                                 "MultiArrayLayout layout\n"
                                 "uint8[] data\n" YDSCOPE_MSG_SEPARATOR
                                 "MSG: std_msgs/MultiArrayLayout\n"
                                 "MultiArrayDimension[] dim\n"
                                 "uint32 data_offset\n" YDSCOPE_MSG_SEPARATOR
                                 "MSG: std_msgs/MultiArrayDimension\n"
                                 "string label\n"
                                 "uint32 size\n"
                                 "uint32 stride\n"};

// /tf_static: where each of several lidars sits (ros_tf.h).
const RosSchema kTfMessage{"tf2_msgs/msg/TFMessage",
                           "geometry_msgs/TransformStamped[] transforms\n" YDSCOPE_MSG_SEPARATOR
                           "MSG: geometry_msgs/TransformStamped\n"
                           "std_msgs/Header header\n"
                           "string child_frame_id\n"
                           "Transform transform\n" YDSCOPE_HEADER_DEPENDENCIES YDSCOPE_MSG_SEPARATOR
                           "MSG: geometry_msgs/Transform\n"
                           "Vector3 translation\n"
                           "Quaternion rotation\n" YDSCOPE_MSG_SEPARATOR
                           "MSG: geometry_msgs/Vector3\n"
                           "float64 x\n"
                           "float64 y\n"
                           "float64 z\n" YDSCOPE_MSG_SEPARATOR
                           "MSG: geometry_msgs/Quaternion\n"
                           "float64 x 0\n"
                           "float64 y 0\n"
                           "float64 z 0\n"
                           "float64 w 1\n"};

#undef YDSCOPE_HEADER_DEPENDENCIES
#undef YDSCOPE_MSG_SEPARATOR

}  // namespace

const RosSchema& laser_scan_schema() { return kLaserScan; }
const RosSchema& tf_message_schema() { return kTfMessage; }
const RosSchema& point_cloud2_schema() { return kPointCloud2; }
const RosSchema& diagnostic_array_schema() { return kDiagnosticArray; }
const RosSchema& uint8_multi_array_schema() { return kUInt8MultiArray; }

}  // namespace ydscope
