#include "ui/view/scene/booth_framing.h"

#include <algorithm>
#include <array>
#include <cmath>

namespace ydscope::ui {

float booth_frame_range_mm(const MotionBackground& room, Vec2 view_size) {
  if (view_size.x <= 0.0f || view_size.y <= 0.0f) return 0.0f;
  // A return at (x, y) on screen fits a radius-r fit of the shorter half when r >= |x| * short/half_w
  // and r >= |y| * short/half_h: each direction's room, scaled to the radius it needs.
  const float shorter = std::min(view_size.x, view_size.y);
  const float sx = shorter / view_size.x, sy = shorter / view_size.y;
  std::array<float, MotionBackground::kBins> needed{};
  std::size_t n = 0;
  for (std::size_t bin = 0; bin < MotionBackground::kBins; ++bin) {
    const float angle = (static_cast<float>(bin) + 0.5f) * 360.0f / static_cast<float>(MotionBackground::kBins);
    const float range = room.background_mm(angle);
    if (range <= 0.0f) continue;
    const Vec2 p = polar_to_world(angle, range);
    needed[n++] = std::max(std::abs(p.x) * sx, std::abs(p.y) * sy);
  }
  if (n < MotionBackground::kBins / 4) return 0.0f;
  const auto k = static_cast<std::size_t>(std::lround(kBoothFramedShare * static_cast<float>(n - 1)));
  std::nth_element(needed.begin(), needed.begin() + static_cast<std::ptrdiff_t>(k),
                   needed.begin() + static_cast<std::ptrdiff_t>(n));
  return needed[k] * 1.05f;  // a margin, so the walls do not touch the edge
}

}  // namespace ydscope::ui
