#pragma once
// Where each lidar sits, for ROS: its pose (core/frame/pose.h) as the transform from the robot's
// frame (REP-103, x forward, y left) to that lidar's laser frame, published once on /tf_static as
// tf2_msgs/msg/TFMessage.
//
// The pose is already in ROS terms: with the official driver's frame (reversion and inverted, the
// defaults) the transform is the pose itself: translation (x, y, 0), a turn of yaw about z, and
// for an upside-down mount a roll of 180 degrees about the laser's x axis. That laser frame puts
// the unit's 0 degrees on -x and its clockwise sweep counter-clockwise in ROS angles (180 - a).
// Other RosFrameOptions move where a device angle lands in /scan and /points; the transform then
// includes that turn (or mirror, for reversion without inverted), so the points land in the same
// place whatever the options.
#include <cstdint>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "core/export/ros_encoding.h"
#include "core/frame/pose.h"

namespace ydscope {

struct RosTransform {
  std::string parent_frame;
  std::string child_frame;
  double translation[3] = {0, 0, 0};  // metres
  double rotation[4] = {0, 0, 0, 1};  // quaternion x, y, z, w
};

RosTransform ros_transform_of(const Pose& pose, const RosFrameOptions& frame, std::string parent, std::string child);

// The unit's own angles as a frame under the laser frame, so /tf_static says how they map: x along
// the unit's 0 degrees, y along its 90, and z = x cross y, which points down with the official
// driver's frame (the unit sweeps clockwise seen from above). A device angle a is then the usual
// counter-clockwise angle about that z. With the defaults it is a turn of 180 degrees about y.
RosTransform ros_unit_transform(const RosFrameOptions& frame, const std::string& laser_frame);
inline std::string unit_frame_id(std::string_view laser_frame) { return std::string(laser_frame) + "_unit"; }

// What /tf_static says of one lidar: its mount (parent -> laser frame) and its unit frame.
void append_lidar_transforms(const Pose& pose, const RosFrameOptions& frame, const std::string& parent,
                             const std::string& laser_frame, std::vector<RosTransform>& out);

// tf2_msgs/msg/TFMessage in CDR: every transform, each stamped `stamp_ns` (ns since the Unix epoch).
void encode_tf_message(std::span<const RosTransform> transforms, std::uint64_t stamp_ns,
                       std::vector<std::uint8_t>& out);

}  // namespace ydscope
