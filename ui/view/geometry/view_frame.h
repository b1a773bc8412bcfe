#pragma once
// Between the REP-103 frames of core/frame/pose.h (x forward, y left) and the view's world (x
// right, y up the screen): forward is drawn up and left to the left, as ROS tools draw a robot
// seen from above. The map is a quarter turn, so a counter-clockwise yaw turns a cloud
// counter-clockwise on screen.
#include "core/frame/pose.h"
#include "ui/view/geometry/geometry.h"

namespace ydscope::ui {

inline Vec2 view_of(CommonPoint p) { return {-p.y_mm, p.x_mm}; }
inline CommonPoint common_of(Vec2 world) { return {world.y, -world.x}; }

// A point of a lone lidar's picture (its laser frame, drawn as polar_to_world draws it) where
// `pose` puts it in the common frame's picture.
inline Vec2 posed_in_view(const PosedFrame& frame, Vec2 lone) { return view_of(frame.to_common(common_of(lone))); }
inline Vec2 posed_in_view(const Pose& pose, Vec2 lone) { return posed_in_view(PosedFrame(pose), lone); }

}  // namespace ydscope::ui
