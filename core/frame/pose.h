#pragma once
// Where a lidar sits in the common frame several lidars share: a position, a heading, and whether
// it is mounted upside down. Plain C++ (no GL), so the app's view, the CLI, recordings and the ROS
// export use one definition.
//
// Frames follow REP-103, seen from above: the common frame is the robot's (x forward, y left,
// millimetres), and a lidar's own frame is its laser frame as the official ROS driver publishes it
// (YDLidar-SDK with `reversion` and `inverted`, as the driver's G1, G6 and TG parameter files set):
// the unit's 0 degrees points along -x, and its clockwise sweep seen from above runs through +y at
// 90, +x at 180 and -y at 270. A lap point at device angle a and range r lies at (-r cos a, r sin a)
// in the laser frame. The pose maps that frame into the common one: first the unit's angle offset
// (degrees added to its angles, clockwise as they are: where its 0 really points), then the mirror
// of an upside-down mount (a roll of 180 degrees about the laser's x axis: y becomes -y, a becomes
// 360 - a), then a rotation by yaw (degrees, counter-clockwise positive), then the shift by (x, y).
// A lidar at "0,0,0" faces the robot's forward with its 180 degrees.
//
// Text form (--pose, recordings' metadata, settings.ini): "x,y,yaw", then optionally "flip" and
// "offset=DEG"; x and y in metres, yaw in degrees; "flip" marks the upside-down mount, "offset="
// the unit's angle offset. "0.2,-0.15,90", "0,0,180,flip" and "0,0,0,flip,offset=-2.5" are poses. Poses written before REP-103 (x right, y forward) are converted on load:
// core/frame/pose_convention.h.
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "core/protocol/lap.h"

namespace ydscope {

// Positions beyond this are a typo (a value in mm given as metres), not a robot.
inline constexpr double kMaxPoseOffsetM = 1000.0;

// A point in a frame seen from above, REP-103 axes: x forward, y left, millimetres.
struct CommonPoint {
  float x_mm = 0;
  float y_mm = 0;
};

// A lap point in its lidar's laser frame (see above).
CommonPoint laser_point(const LapPoint& point);

struct Pose {
  double x_m = 0;
  double y_m = 0;
  double yaw_deg = 0;           // within [-360, 360]
  bool upside_down = false;     // mounted head down: angles mirrored
  double angle_offset_deg = 0;  // added to the unit's angles, within [-360, 360]

  // A point of this lidar's lap in the common frame. A point without a return (range 0) lands on
  // the lidar's own position; callers that draw returns skip those first.
  CommonPoint to_common(const LapPoint& point) const;
  // A point of the lidar's laser frame in the common frame.
  CommonPoint to_common(CommonPoint laser) const;
  // Every point of `lap`, in order, into `out` (replaced; its capacity is reused).
  void to_common(const Lap& lap, std::vector<CommonPoint>& out) const;
  // The inverse: a common-frame point in the lidar's laser frame.
  CommonPoint to_laser(CommonPoint common) const;

  friend bool operator==(const Pose&, const Pose&) = default;
};

// A pose with its turns worked out once, for placing many points: Pose::to_common works out the
// sines and cosines of the yaw and the angle offset again at each point (with eight lidars, sines
// and cosines were about a tenth of the app's main thread). Gives what Pose::to_common gives.
class PosedFrame {
 public:
  explicit PosedFrame(const Pose& pose);
  CommonPoint to_common(const LapPoint& point) const { return to_common(laser_point(point)); }
  CommonPoint to_common(CommonPoint laser) const;

 private:
  double offset_cos_, offset_sin_, yaw_cos_, yaw_sin_, x_mm_, y_mm_;
  bool upside_down_;
};

// Parses the text form. Empty plus one sentence in `error` that says what was wrong.
std::optional<Pose> parse_pose(std::string_view text, std::string& error);
// The text form again; parse_pose(format_pose(p)) == p.
std::string format_pose(const Pose& pose);

}  // namespace ydscope
