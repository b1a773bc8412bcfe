#include "ui/view/window/window_fit.h"

#include <algorithm>
#include <cmath>

namespace ydscope::ui {
namespace {

int scaled(int px, float scale) {
  return static_cast<int>(std::lround(static_cast<float>(px) * std::max(scale, 0.5f)));
}

}  // namespace

bool window_was_shrunk(ScreenRect area, float scale) {
  if (area.width <= 0 || area.height <= 0) return false;
  return scaled(kPreferredWindowWidth, scale) > area.width ||
         scaled(kPreferredWindowHeight, scale) > area.height - scaled(kTitleBarAllowance, scale);
}

ScreenRect first_window_rect(ScreenRect area, float scale) {
  ScreenRect r{0, 0, scaled(kPreferredWindowWidth, scale), scaled(kPreferredWindowHeight, scale)};
  if (area.width <= 0 || area.height <= 0) return r;
  r.width = std::min(r.width, area.width);
  r.height = std::min(r.height, area.height);
  r.x = area.x + (area.width - r.width) / 2;
  r.y = area.y + (area.height - r.height) / 2;
  return r;
}

float sidebar_width(float window_width, float scale) {
  return std::min(430.0f * std::max(scale, 0.5f), 0.4f * window_width);
}

float sidebar_max_width(float window_width) { return std::max(0.45f * window_width, 200.0f); }

}  // namespace ydscope::ui
