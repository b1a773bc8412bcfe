#pragma once
// Where several lidars sit, for ROS: each pose (core/frame/pose.h) as a transform from a common
// frame to that lidar's laser frame, published once on /tf_static as tf2_msgs/msg/TFMessage.
//
// The laser frame's axes follow RosFrameOptions (reversion, inverted), which decide where a point
// at device angle a lands in /scan and /points. The common frame is the laser frame of a lidar at
// the origin pose, so a lidar at "0,0,0" has the identity transform, and every other transform
// moves and turns the laser frame exactly as the pose moves the lidar's points in the app's view.
// An upside-down mount, or a frame option that makes the laser frame mirrored (reversion without
// inverted), is a roll of 180 degrees about the transform's x axis.
#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "core/export/ros_encoding.h"
#include "core/frame/pose.h"

namespace ydscope {

// The common frame's id in /tf_static.
inline constexpr const char* kCommonFrameId = "ydscope";

struct RosTransform {
  std::string parent_frame;
  std::string child_frame;
  double translation[3] = {0, 0, 0};  // metres
  double rotation[4] = {0, 0, 0, 1};  // quaternion x, y, z, w
};

RosTransform ros_transform_of(const Pose& pose, const RosFrameOptions& frame, std::string parent, std::string child);

// tf2_msgs/msg/TFMessage in CDR: every transform, each stamped `stamp_ns` (ns since the Unix epoch).
void encode_tf_message(std::span<const RosTransform> transforms, std::uint64_t stamp_ns,
                       std::vector<std::uint8_t>& out);

}  // namespace ydscope
