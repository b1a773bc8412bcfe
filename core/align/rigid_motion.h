#pragma once
// A turn about a centre followed by a shift, in the common frame's millimetres: how alignment moves
// a lidar's cloud. Turning about the lidar's own position keeps the turn and the shift apart, so a
// search over one does not drag the other along.
#include <cmath>

#include "core/frame/pose.h"

namespace ydscope::align {

struct Point2 {
  double x = 0;
  double y = 0;
};

struct RigidMotion {
  double turn_rad = 0;  // counter-clockwise in the common frame's x-y plane
  Point2 centre;        // mm
  Point2 shift;         // mm

  Point2 apply(Point2 p) const {
    const double c = std::cos(turn_rad), s = std::sin(turn_rad);
    const double dx = p.x - centre.x, dy = p.y - centre.y;
    return {c * dx - s * dy + centre.x + shift.x, s * dx + c * dy + centre.y + shift.y};
  }
};

// Where a lidar stands in the common frame (mm), by core/frame's own transform.
Point2 pose_position_mm(const Pose& pose);

// The pose whose transform is `motion` after `pose`: the lidar's cloud moved as `motion` moves it.
// Found through Pose::to_common (not by assuming which way its yaw turns), so it follows core/frame.
Pose moved_pose(const Pose& pose, const RigidMotion& motion);

// The motion that takes `from`'s cloud to `to`'s, about from's position (for reporting how far a
// start was from the truth, and for tests).
RigidMotion motion_between(const Pose& from, const Pose& to);

}  // namespace ydscope::align
