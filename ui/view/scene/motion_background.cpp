#include "ui/view/scene/motion_background.h"

#include <algorithm>
#include <cmath>

namespace ydscope::ui {

MotionBackground::MotionBackground() : history_(kBins * kLaps, 0.0f) {}

std::size_t MotionBackground::bin_of(float angle_deg) {
  float a = std::fmod(angle_deg, 360.0f);
  if (a < 0.0f) a += 360.0f;
  return std::min(static_cast<std::size_t>(a * (static_cast<float>(kBins) / 360.0f)), kBins - 1);
}

void MotionBackground::clear() {
  std::fill(history_.begin(), history_.end(), 0.0f);
  background_.fill(0.0f);
  next_ = 0;
  laps_seen_ = 0;
}

void MotionBackground::add_lap(const Lap& lap) {
  lap_max_.fill(0.0f);
  for (const LapPoint& p : lap.points)
    if (p.range_mm > 0.0f) {
      float& m = lap_max_[bin_of(p.angle_deg)];
      m = std::max(m, p.range_mm);
    }
  for (std::size_t bin = 0; bin < kBins; ++bin) history_[bin * kLaps + next_] = lap_max_[bin];
  next_ = (next_ + 1) % kLaps;
  ++laps_seen_;
  for (std::size_t bin = 0; bin < kBins; ++bin) update_background(bin);
}

void MotionBackground::update_background(std::size_t bin) {
  std::array<float, kLaps> ranges;
  std::size_t n = 0;
  for (std::size_t i = 0; i < kLaps; ++i)
    if (const float r = history_[bin * kLaps + i]; r > 0.0f) ranges[n++] = r;
  // Learned once a quarter of the window saw a return there.
  if (n < kLaps / 4 || n * 2 < std::min(laps_seen_, kLaps)) {
    background_[bin] = 0.0f;
    return;
  }
  const auto k =
      static_cast<std::ptrdiff_t>(std::min(n - 1, static_cast<std::size_t>(kQuantile * static_cast<float>(n))));
  std::nth_element(ranges.begin(), ranges.begin() + k, ranges.begin() + static_cast<std::ptrdiff_t>(n));
  background_[bin] = ranges[static_cast<std::size_t>(k)];
}

float MotionBackground::background_mm(float angle_deg) const { return background_[bin_of(angle_deg)]; }

bool MotionBackground::is_moving(const LapPoint& point) const {
  if (point.range_mm <= 0.0f) return false;
  const float room = background_mm(point.angle_deg);
  return room > 0.0f && point.range_mm < room - std::max(kCloserMm, kCloserShare * room);
}

}  // namespace ydscope::ui
