#include "ui/view/geometry/grid_geometry.h"

#include <algorithm>
#include <cmath>

namespace ydscope::ui {
namespace {

// One segment as two triangles, widened by `half_mm` on each side.
void push_segment(std::vector<LineVertex>& out, Vec2 a, Vec2 b, float half_mm, float half_px, Rgba8 colour) {
  const Vec2 d = b - a;
  const float len = length(d);
  if (len <= 0.0f) return;
  const Vec2 n{-d.y / len * half_mm, d.x / len * half_mm};
  const LineVertex a0{a.x + n.x, a.y + n.y, half_px, colour};
  const LineVertex a1{a.x - n.x, a.y - n.y, -half_px, colour};
  const LineVertex b0{b.x + n.x, b.y + n.y, half_px, colour};
  const LineVertex b1{b.x - n.x, b.y - n.y, -half_px, colour};
  out.insert(out.end(), {a0, a1, b0, b0, a1, b1});
}

}  // namespace

float line_quad_half_px(const GridStyle& style) { return 0.5f * style.line_width_px + 1.0f; }

void build_grid_geometry(const ViewTransform& view, const GridLayout& grid, const GridStyle& style,
                         std::vector<LineVertex>& out) {
  out.clear();
  const float ppm = view.px_per_mm();
  const float half_px = line_quad_half_px(style);
  const float half_mm = half_px / ppm;
  constexpr float kTwoPi = 6.28318530718f;
  for (const float r : grid.ring_radii_mm) {
    // About one segment per 6 pixels of circumference: smooth, and bounded when zoomed far in.
    const int segments = std::clamp(static_cast<int>(r * ppm * kTwoPi / 6.0f), 48, 1440);
    const bool major = std::fmod(std::round(r / grid.ring_step_mm), 5.0f) == 0.0f;
    const Rgba8 colour = major ? style.major_ring : style.ring;
    Vec2 prev{0.0f, r};
    for (int i = 1; i <= segments; ++i) {
      const float a = kTwoPi * static_cast<float>(i) / static_cast<float>(segments);
      const Vec2 next{r * std::sin(a), r * std::cos(a)};
      push_segment(out, prev, next, half_mm, half_px, colour);
      prev = next;
    }
  }
  const float outer = grid.ring_radii_mm.empty() ? view.visible_radius_mm() : grid.ring_radii_mm.back();
  const float inner = style.spoke_start_px / ppm;
  if (outer > inner) {
    for (const float angle : grid.spoke_angles_deg) {
      push_segment(out, polar_to_world(angle, inner), polar_to_world(angle, outer), half_mm, half_px, style.spoke);
    }
  }
}

}  // namespace ydscope::ui
