#pragma once
// What the booth view frames: the scene the lidar sees, not the rings of its longest reach. The
// furthest steady returns (the room MotionBackground learned, so a visitor walking close does not
// shrink the view and a far stray return does not widen it) are fitted to the screen's shape: a
// stand that is wide and shallow fills a wide screen. The answer is the radius to hand to
// auto-range, which fits a radius into the shorter half of the view.
#include "ui/view/geometry/geometry.h"
#include "ui/view/scene/motion_background.h"

namespace ydscope::ui {

// Share of the learned directions whose room must fit in the view (the rest: a door, a gap to a far hall).
inline constexpr float kBoothFramedShare = 0.95f;

// 0 while the room is not learned yet (fewer than a quarter of the directions have a background),
// so the caller keeps the usual auto-range. `view_size` is the view's size in pixels.
float booth_frame_range_mm(const MotionBackground& room, Vec2 view_size);

}  // namespace ydscope::ui
