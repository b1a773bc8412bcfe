#include "ui/view/scene/lap_phase.h"

#include <algorithm>

namespace ydscope::ui {
namespace {

// Laps further apart than this are a stall or a pause, not the lidar's rate (the slowest
// supported scan is 5 Hz; a replay at 0.1x stretches that to 2 s).
constexpr double kLongestPeriodS = 3.0;
// Weight of the newest interval: a scan-rate change settles in a few laps, while one late lap
// (a busy frame, a burst from a USB adapter) barely moves the estimate.
constexpr double kNewWeight = 0.25;

}  // namespace

void LapPhase::on_lap(double now_s) {
  if (last_lap_s_) {
    const double interval = now_s - *last_lap_s_;
    if (interval > 0.0 && interval <= kLongestPeriodS)
      period_s_ = period_s_ > 0.0 ? period_s_ + kNewWeight * (interval - period_s_) : interval;
    else if (interval > kLongestPeriodS)
      period_s_ = 0.0;
  }
  last_lap_s_ = now_s;
}

float LapPhase::at(double now_s) const {
  if (!last_lap_s_ || period_s_ <= 0.0) return 0.0f;
  return static_cast<float>(std::clamp((now_s - *last_lap_s_) / period_s_, 0.0, 1.0));
}

void LapPhase::reset() {
  last_lap_s_.reset();
  period_s_ = 0.0;
}

}  // namespace ydscope::ui
