#include "ui/view/window/frame_pacing.h"

#include <algorithm>
#include <string_view>

namespace ydscope::ui {
namespace {

double sane_hz(double hz) { return hz >= 24.0 && hz <= 500.0 ? hz : 60.0; }

}  // namespace

double frame_wait_s(const FrameNeeds& needs, double since_frame_s, double refresh_hz) {
  if (needs.screenshot) return 0.02;
  if (needs.animating) {
    // Paced by the clock as well as by the swap: without vsync (Xvfb, some drivers) swapping
    // returns at once and the loop would spin a core.
    return std::max(0.0, 1.0 / sane_hz(refresh_hz) - since_frame_s);
  }
  // With nothing arriving, one frame a second keeps the link state and the lap age current at
  // almost no cost.
  return needs.streaming ? 0.25 : 1.0;
}

bool is_software_renderer(const char* gl_renderer) {
  const std::string_view renderer = gl_renderer != nullptr ? gl_renderer : "";
  bool software = false;
  for (const std::string_view name : {"llvmpipe", "softpipe", "swrast", "SwiftShader", "Software Rasterizer"})
    software = software || renderer.find(name) != std::string_view::npos;
  return software;
}

double animation_hz(double monitor_hz, const char* gl_renderer) {
  const double hz = sane_hz(monitor_hz);
  return is_software_renderer(gl_renderer) ? std::min(hz, kSoftwareRendererHz) : hz;
}

}  // namespace ydscope::ui
