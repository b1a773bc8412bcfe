#include "core/align/rigid_motion.h"

#include <numbers>

namespace ydscope::align {
namespace {

constexpr float kProbeMm = 1000.0f;

Point2 common(const Pose& pose, float angle_deg, float range_mm) {
  const CommonPoint p = pose.to_common(LapPoint{angle_deg, range_mm, PointFlag::None});
  return {p.x_mm, p.y_mm};
}

double wrap_degrees(double degrees) {
  degrees = std::fmod(degrees, 360.0);
  if (degrees > 180.0) degrees -= 360.0;
  if (degrees <= -180.0) degrees += 360.0;
  return degrees + 0.0;  // never -0
}

// The direction, in the common frame, of the lidar's 0 degree ray.
double heading_rad(const Pose& pose) {
  const Point2 at = pose_position_mm(pose);
  const Point2 ahead = common(pose, 0.0f, kProbeMm);
  return std::atan2(ahead.y - at.y, ahead.x - at.x);
}

}  // namespace

Point2 pose_position_mm(const Pose& pose) { return common(pose, 0.0f, 0.0f); }

Pose moved_pose(const Pose& pose, const RigidMotion& motion) {
  const Point2 at = motion.apply(pose_position_mm(pose));
  const double turn_deg = motion.turn_rad * 180.0 / std::numbers::pi;
  Pose moved = pose;
  moved.x_m = at.x / 1000.0;
  moved.y_m = at.y / 1000.0;
  // The pose's yaw turns its cloud one way or the other in the common frame, as core/frame has it:
  // take the sign that turns the 0 degree ray as `motion` does.
  moved.yaw_deg = wrap_degrees(pose.yaw_deg + turn_deg);
  const double wanted = heading_rad(pose) + motion.turn_rad;
  const double got = heading_rad(moved);
  if (std::abs(std::remainder(got - wanted, 2 * std::numbers::pi)) > 1e-4)  // float points: a sign error is 2 turns off
    moved.yaw_deg = wrap_degrees(pose.yaw_deg - turn_deg);
  return moved;
}

RigidMotion motion_between(const Pose& from, const Pose& to) {
  RigidMotion motion;
  motion.turn_rad = std::remainder(heading_rad(to) - heading_rad(from), 2 * std::numbers::pi);
  motion.centre = pose_position_mm(from);
  const Point2 at = pose_position_mm(to);
  motion.shift = {at.x - motion.centre.x, at.y - motion.centre.y};
  return motion;
}

}  // namespace ydscope::align
