#include "ui/view/geometry/unit_marks.h"

#include <algorithm>

#include "ui/view/geometry/view_frame.h"

namespace ydscope::ui {
namespace {

constexpr float kTickFromPx = 11.0f, kTickToPx = 30.0f, kLabelPx = 40.0f, kArcPx = 22.0f;
constexpr float kArcFromDeg = 15.0f, kArcToDeg = 75.0f, kArcStepDeg = 5.0f, kHeadPx = 6.0f;

}  // namespace

UnitMarks unit_marks(const ViewTransform& view, const Pose& pose) {
  UnitMarks marks;
  marks.centre = view.world_to_screen(view_of(pose.to_common(CommonPoint{0.0f, 0.0f})));
  // The screen direction of device angle a from the lidar's dot.
  const auto towards = [&](float angle_deg) {
    const Vec2 at = view.world_to_screen(view_of(pose.to_common(LapPoint{angle_deg, 1000.0f, PointFlag::None})));
    const Vec2 d = at - marks.centre;
    return d * (1.0f / std::max(length(d), 1e-3f));
  };
  const Vec2 zero = towards(0.0f);
  marks.zero_from = marks.centre + zero * kTickFromPx;
  marks.zero_to = marks.centre + zero * kTickToPx;
  marks.zero_label = marks.centre + zero * kLabelPx;
  for (float a = kArcFromDeg; a <= kArcToDeg + 0.01f; a += kArcStepDeg)
    marks.sweep.push_back(marks.centre + towards(a) * kArcPx);
  const Vec2 end = marks.sweep.back();
  const Vec2 before = marks.sweep[marks.sweep.size() - 2];
  Vec2 along = end - before;
  along = along * (1.0f / std::max(length(along), 1e-3f));
  const Vec2 side{-along.y, along.x};
  marks.head_tip = end + along * kHeadPx;
  marks.head_left = end - along * (kHeadPx * 0.5f) + side * (kHeadPx * 0.8f);
  marks.head_right = end - along * (kHeadPx * 0.5f) - side * (kHeadPx * 0.8f);
  return marks;
}

}  // namespace ydscope::ui
