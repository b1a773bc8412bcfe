#pragma once
// Motion highlighting: the static room, learned per angle bin over the last laps, so the returns
// closer than it (people walking past a booth) can be painted hot and the room calm. Works on any
// model (only angle and range are used). Preallocated: adding a lap allocates nothing.
#include <array>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "core/protocol/lap.h"

namespace ydscope::ui {

class MotionBackground {
 public:
  static constexpr std::size_t kBins = 720;  // half a degree each
  static constexpr std::size_t kLaps = 40;   // about 5 s at 8 Hz
  // A bin's background is this quantile of its ranges over the last laps: someone passing covers
  // a bin for a small share of the time, so the room's range wins.
  static constexpr float kQuantile = 0.75f;
  // Closer than the background by more than this share and distance is motion, not noise.
  static constexpr float kCloserShare = 0.08f;
  static constexpr float kCloserMm = 150.0f;

  MotionBackground();

  void add_lap(const Lap& lap);
  void clear();
  // The room's range at this angle, 0 while not learned (too few laps with a return there).
  float background_mm(float angle_deg) const;
  // A return clearly closer than the learned room at its angle.
  bool is_moving(const LapPoint& point) const;
  std::size_t laps_seen() const { return laps_seen_; }

 private:
  static std::size_t bin_of(float angle_deg);
  void update_background(std::size_t bin);

  // Per bin, the farthest return of each of the last kLaps laps (0: none), as a ring.
  std::vector<float> history_;
  std::array<float, kBins> background_{};
  std::array<float, kBins> lap_max_{};
  std::size_t next_ = 0;
  std::size_t laps_seen_ = 0;
};

}  // namespace ydscope::ui
