#pragma once
// The ROS 2 message definitions ydscope publishes, as `ros2msg` schema text: the type's .msg
// followed by every type it uses, each after a line of 80 '=' and "MSG: package/Type" (the
// delimited format of MCAP's ros1msg/ros2msg schema encodings).
#include <string_view>

namespace ydscope {

struct RosSchema {
  std::string_view name;  // "sensor_msgs/msg/LaserScan"
  std::string_view text;  // the ros2msg schema data
};

const RosSchema& laser_scan_schema();
const RosSchema& point_cloud2_schema();
const RosSchema& diagnostic_array_schema();
// std_msgs/msg/UInt8MultiArray: the raw link bytes, in a type every ROS 2 install has.
const RosSchema& uint8_multi_array_schema();
// tf2_msgs/msg/TFMessage: /tf_static, where each of several lidars sits.
const RosSchema& tf_message_schema();

}  // namespace ydscope
