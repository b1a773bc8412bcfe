#include "ui/view/geometry/pose_drag.h"

#include <cmath>

#include "ui/view/geometry/view_frame.h"

namespace ydscope::ui {
namespace {

constexpr double kRadToDeg = 180.0 / 3.14159265358979323846;

double wrapped_deg(double deg) {
  const double wrapped = std::fmod(deg + 180.0, 360.0);
  return (wrapped < 0 ? wrapped + 360.0 : wrapped) - 180.0;
}

}  // namespace

Pose dragged_pose(const Pose& pose, const PoseDrag& drag) {
  Pose out = pose;
  if (!drag.turn) {
    // The pose is in the common frame (REP-103), the drag in the view's world.
    const CommonPoint from = common_of(drag.from_world);
    const CommonPoint to = common_of(drag.to_world);
    out.x_m += (to.x_mm - from.x_mm) / 1000.0;
    out.y_m += (to.y_mm - from.y_mm) / 1000.0;
    return out;
  }
  // The view is the common frame turned a quarter, so angles swept on screen are yaw angles.
  const Vec2 centre =
      view_of(CommonPoint{static_cast<float>(pose.x_m * 1000.0), static_cast<float>(pose.y_m * 1000.0)});
  const double cx = centre.x, cy = centre.y;
  // A pointer on the lidar itself has no direction to turn by.
  if (std::hypot(drag.from_world.x - cx, drag.from_world.y - cy) < 1.0 ||
      std::hypot(drag.to_world.x - cx, drag.to_world.y - cy) < 1.0)
    return out;
  const double before = std::atan2(drag.from_world.y - cy, drag.from_world.x - cx);
  const double after = std::atan2(drag.to_world.y - cy, drag.to_world.x - cx);
  out.yaw_deg = wrapped_deg(pose.yaw_deg + (after - before) * kRadToDeg);
  return out;
}

}  // namespace ydscope::ui
