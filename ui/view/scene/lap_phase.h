#pragma once
// Where the view stands between two laps, so persistence and trails fade continuously at the
// display's rate instead of stepping once per lap (a G6 at 8 Hz would otherwise redraw 8 times a
// second). 0 when a lap has just arrived, rising to 1 when the next one is due.
#include <optional>

namespace ydscope::ui {

class LapPhase {
 public:
  // A lap went into the history at `now_s` (any steady clock, seconds).
  void on_lap(double now_s);
  // 0..1; 0 until two laps have given a period, and held at 1 while the next lap is late.
  float at(double now_s) const;
  // The smoothed time between laps, 0 while unknown.
  double period_s() const { return period_s_; }
  // A new source, or a gap so long the old period says nothing about the next lap.
  void reset();

 private:
  std::optional<double> last_lap_s_;
  double period_s_ = 0.0;
};

}  // namespace ydscope::ui
