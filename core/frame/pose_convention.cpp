#include "core/frame/pose_convention.h"

#include <cmath>

namespace ydscope {

Pose pose_from_pre_rep103(const Pose& old) {
  Pose pose = old;
  pose.x_m = old.y_m;
  pose.y_m = -old.x_m + 0.0;  // + 0.0: no "-0" in the text form
  double yaw = std::fmod(old.yaw_deg + 180.0, 360.0);
  if (yaw > 180.0) yaw -= 360.0;
  if (yaw <= -180.0) yaw += 360.0;
  pose.yaw_deg = yaw + 0.0;
  return pose;
}

}  // namespace ydscope
