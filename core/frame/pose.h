#pragma once
// Where a lidar sits in the common frame several lidars share: a position, a heading, and whether
// it is mounted upside down. Plain C++ (no GL), so the app's view, the CLI, recordings and the ROS
// export use one definition.
//
// Frames, as the app's polar view draws a single lidar: x to the right, y forward, millimetres,
// seen from above. A lap point at device angle a (degrees, clockwise from the lidar's 0) and range
// r lies at (r sin a, r cos a) in the lidar's own frame. The pose maps that frame into the common
// one: first the mirror of an upside-down mount (the head then spins the other way as seen from
// above: a becomes 360 - a), then a rotation by yaw (degrees, counter-clockwise positive as seen
// from above, as ROS yaw turns), then the shift by (x, y).
//
// Text form (--pose, recordings' metadata): "x,y,yaw" or "x,y,yaw,flip", x and y in metres, yaw in
// degrees; "flip" marks the upside-down mount. "0.2,-0.15,90" and "0,0,180,flip" are poses.
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "core/protocol/lap.h"

namespace ydscope {

// Positions beyond this are a typo (a value in mm given as metres), not a robot.
inline constexpr double kMaxPoseOffsetM = 1000.0;

struct CommonPoint {
  float x_mm = 0;
  float y_mm = 0;
};

struct Pose {
  double x_m = 0;
  double y_m = 0;
  double yaw_deg = 0;        // within [-360, 360]
  bool upside_down = false;  // mounted head down: angles mirrored

  // A point of this lidar's lap in the common frame. A point without a return (range 0) lands on
  // the lidar's own position; callers that draw returns skip those first.
  CommonPoint to_common(const LapPoint& point) const;
  // A point of the lidar's own frame (x = r sin a, y = r cos a, as a single lidar's view draws
  // it) in the common frame: the view poses a cloud it has already laid out this way.
  CommonPoint to_common(CommonPoint own) const;
  // Every point of `lap`, in order, into `out` (replaced; its capacity is reused).
  void to_common(const Lap& lap, std::vector<CommonPoint>& out) const;
  // The device angle as the common frame's clockwise-from-forward angle, in [0, 360): what a
  // polar view around the lidar's position, turned with the common frame, shows it at.
  double common_angle_deg(double device_angle_deg) const;

  friend bool operator==(const Pose&, const Pose&) = default;
};

// Parses the text form. Empty plus one sentence in `error` that says what was wrong.
std::optional<Pose> parse_pose(std::string_view text, std::string& error);
// The text form again; parse_pose(format_pose(p)) == p.
std::string format_pose(const Pose& pose);

}  // namespace ydscope
