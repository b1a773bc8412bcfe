#pragma once
// "This wall is straight ahead": a click on the view that sets a lidar's yaw so the clicked point
// lies on the robot's forward axis (+x, REP-103) as seen from the lidar. The lidar turns about its
// own position, so the point it saw there turns with it; its position, mirror and angle offset
// stay. Plain math, tested without a display.
#include <optional>

#include "core/frame/pose.h"

namespace ydscope::ui {

// `pose` turned so that `laser` (a point of the lidar's laser frame, where it saw the clicked
// thing) lies straight ahead of it in the common frame; the yaw kept within (-180, 180]. Empty
// for a point on the lidar itself (no direction).
std::optional<Pose> facing_forward(const Pose& pose, CommonPoint laser);

}  // namespace ydscope::ui
