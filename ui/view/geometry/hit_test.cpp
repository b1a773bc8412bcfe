#include "ui/view/geometry/hit_test.h"

#include <cmath>

namespace ydscope::ui {

std::optional<PointHit> nearest_point(std::span<const LapPoint> points, const ViewTransform& view, Vec2 cursor_px,
                                      float max_distance_px) {
  // Compare in world units: one conversion of the cursor instead of one per point.
  const Vec2 cursor_world = view.screen_to_world(cursor_px);
  const float max_mm = max_distance_px / view.px_per_mm();
  float best = max_mm * max_mm;
  std::optional<PointHit> hit;
  for (const LapPoint& p : points) {
    if (p.range_mm <= 0.0f) continue;
    const Vec2 w = polar_to_world(p.angle_deg, p.range_mm);
    const float d2 = length_squared(w - cursor_world);
    if (d2 <= best) {
      best = d2;
      hit = PointHit{p, w, std::sqrt(d2) * view.px_per_mm()};
    }
  }
  return hit;
}

void Ruler::click(Vec2 world_mm) {
  if (!first_ || second_) {
    first_ = world_mm;
    second_.reset();
  } else {
    second_ = world_mm;
  }
}

std::optional<float> Ruler::length_mm() const {
  if (!complete()) return std::nullopt;
  return length(*second_ - *first_);
}

}  // namespace ydscope::ui
