#include "ui/view/geometry/grid_layout.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace ydscope::ui {

float nice_ring_step_mm(float px_per_mm, float min_px) {
  const float min_mm = min_px / std::max(px_per_mm, 1e-9f);
  float decade = std::pow(10.0f, std::floor(std::log10(std::max(min_mm, 1e-3f))));
  for (int guard = 0; guard < 40; ++guard) {
    for (const float m : {1.0f, 2.0f, 5.0f}) {
      if (m * decade >= min_mm) return m * decade;
    }
    decade *= 10.0f;
  }
  return decade;
}

std::string format_distance(float mm) {
  char text[32];
  if (mm < 100.0f) {
    std::snprintf(text, sizeof text, "%g mm", static_cast<double>(std::round(mm)));
  } else if (mm < 1000.0f) {
    std::snprintf(text, sizeof text, "%g cm", static_cast<double>(std::round(mm / 10.0f)));
  } else {
    // Two decimals at most: 1.25 m, 2.5 m, 10 m.
    std::snprintf(text, sizeof text, "%g m", static_cast<double>(std::round(mm / 10.0f) / 100.0f));
  }
  return text;
}

namespace {

// Where a ray from `from` along `dir` leaves the rectangle [lo, hi]; false if it never is inside.
bool ray_exit(Vec2 from, Vec2 dir, Vec2 lo, Vec2 hi, Vec2& exit) {
  float t_enter = 0.0f;
  float t_exit = 1e30f;
  const float origin[2] = {from.x, from.y};
  const float d[2] = {dir.x, dir.y};
  const float mins[2] = {lo.x, lo.y};
  const float maxs[2] = {hi.x, hi.y};
  for (int axis = 0; axis < 2; ++axis) {
    if (std::fabs(d[axis]) < 1e-9f) {
      if (origin[axis] < mins[axis] || origin[axis] > maxs[axis]) return false;
      continue;
    }
    float t0 = (mins[axis] - origin[axis]) / d[axis];
    float t1 = (maxs[axis] - origin[axis]) / d[axis];
    if (t0 > t1) std::swap(t0, t1);
    t_enter = std::max(t_enter, t0);
    t_exit = std::min(t_exit, t1);
  }
  if (t_exit < t_enter) return false;
  exit = from + dir * t_exit;
  return true;
}

}  // namespace

float ring_spacing_px(Vec2 viewport_size) {
  constexpr float kRingsAcrossHalf = 5.0f;
  return std::max(70.0f, std::min(viewport_size.x, viewport_size.y) * 0.5f / kRingsAcrossHalf);
}

GridLayout layout_grid(const ViewTransform& view, float min_ring_px, float spoke_step_deg, float label_angle_deg,
                       float edge_margin_px, float status_band_px) {
  GridLayout grid;
  grid.ring_step_mm = nice_ring_step_mm(view.px_per_mm(), min_ring_px);
  const float visible = view.visible_radius_mm();
  // Rings inside the visible radius only; at most a few hundred even when panned far out.
  const float first = std::max(
      grid.ring_step_mm, std::floor((length(view.centre_world()) - visible) / grid.ring_step_mm) * grid.ring_step_mm);
  const Vec2 lo = view.viewport_origin() + Vec2{edge_margin_px, edge_margin_px};
  const Vec2 hi = view.viewport_origin() + view.viewport_size() - Vec2{edge_margin_px, edge_margin_px + status_band_px};
  for (float r = first; r <= visible && grid.ring_radii_mm.size() < 400; r += grid.ring_step_mm) {
    grid.ring_radii_mm.push_back(r);
    // A label near the window's edge would be cut off or touch it: that ring goes unlabelled.
    const Vec2 at = view.world_to_screen(polar_to_world(label_angle_deg, r));
    if (at.x >= lo.x && at.y >= lo.y && at.x <= hi.x - kRingLabelWidthPx && at.y + kLabelHeightPx <= hi.y)
      grid.ring_labels.push_back({at, format_distance(r)});
  }

  const Vec2 origin = view.world_to_screen({0.0f, 0.0f});
  for (float a = 0.0f; a < 359.999f; a += spoke_step_deg) {
    grid.spoke_angles_deg.push_back(a);
    const Vec2 w = polar_to_world(a, 1.0f);
    const Vec2 dir{w.x, -w.y};  // screen y grows downwards
    Vec2 exit;
    if (ray_exit(origin, dir, lo, hi, exit)) {
      char text[16];
      std::snprintf(text, sizeof text, "%d\xC2\xB0", static_cast<int>(std::lround(a)));
      grid.spoke_labels.push_back({exit, text});
    }
  }
  return grid;
}

float robust_max_range_mm(std::span<const LapPoint> points, float fraction) {
  // A fixed histogram (10 cm bins to 100 m) avoids sorting or allocating per frame.
  constexpr std::size_t kBins = 1000;
  constexpr float kBinMm = 100.0f;
  std::array<std::uint32_t, kBins> histogram{};
  std::size_t total = 0;
  for (const LapPoint& p : points) {
    if (p.range_mm <= 0.0f) continue;
    const auto bin = std::min(static_cast<std::size_t>(p.range_mm / kBinMm), kBins - 1);
    ++histogram[bin];
    ++total;
  }
  if (total == 0) return 0.0f;
  const auto wanted =
      static_cast<std::size_t>(std::ceil(static_cast<double>(total) * std::clamp(fraction, 0.0f, 1.0f)));
  std::size_t seen = 0;
  for (std::size_t bin = 0; bin < kBins; ++bin) {
    seen += histogram[bin];
    if (seen >= wanted) return static_cast<float>(bin + 1) * kBinMm;
  }
  return static_cast<float>(kBins) * kBinMm;
}

}  // namespace ydscope::ui
