#include "ui/view/frame_pacing.h"

#include <algorithm>

namespace ydscope::ui {

double frame_wait_s(const FrameNeeds& needs, double since_frame_s, double refresh_hz) {
  if (needs.screenshot) return 0.02;
  if (needs.animating) {
    // Paced by the clock as well as by the swap: without vsync (Xvfb, some drivers) swapping
    // returns at once and the loop would spin a core.
    const double hz = refresh_hz >= 24.0 && refresh_hz <= 500.0 ? refresh_hz : 60.0;
    return std::max(0.0, 1.0 / hz - since_frame_s);
  }
  // With nothing arriving, one frame a second keeps the link state and the lap age current at
  // almost no cost.
  return needs.streaming ? 0.25 : 1.0;
}

}  // namespace ydscope::ui
