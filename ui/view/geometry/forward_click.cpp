#include "ui/view/geometry/forward_click.h"

#include <cmath>
#include <numbers>

namespace ydscope::ui {

std::optional<Pose> facing_forward(const Pose& pose, CommonPoint laser) {
  // The point as the mount turns it before the yaw: mirrored and offset, not yet turned or moved.
  Pose unturned = pose;
  unturned.x_m = unturned.y_m = 0.0;
  unturned.yaw_deg = 0.0;
  const CommonPoint u = unturned.to_common(laser);
  if (std::hypot(u.x_mm, u.y_mm) < 1.0f) return std::nullopt;
  double yaw = -std::atan2(static_cast<double>(u.y_mm), static_cast<double>(u.x_mm)) * 180.0 / std::numbers::pi;
  if (yaw <= -180.0) yaw += 360.0;
  Pose out = pose;
  out.yaw_deg = std::round(yaw * 100.0) / 100.0 + 0.0;  // a hundredth of a degree, as settings keep it; no -0
  return out;
}

}  // namespace ydscope::ui
