#pragma once
// Setting a lidar's pose with the mouse, so two lidars' walls can be lined up by eye: a drag moves
// its cloud as far as the pointer went in the common frame, a drag with the turn modifier turns it
// about its own position by the angle the pointer swept round that position. Plain math over the
// view's world coordinates (ViewTransform::screen_to_world), tested without a display.
#include "core/frame/pose.h"
#include "ui/view/geometry/geometry.h"

namespace ydscope::ui {

// One frame's drag on the view, in world millimetres (the common frame).
struct PoseDrag {
  Vec2 from_world;
  Vec2 to_world;
  bool turn = false;  // turn about the lidar's position instead of moving it
};

// `pose` after the drag: moved by to - from, or turned by the angle from -> to makes about its
// position (counter-clockwise positive, as yaw is), the yaw kept within [-180, 180).
Pose dragged_pose(const Pose& pose, const PoseDrag& drag);

}  // namespace ydscope::ui
