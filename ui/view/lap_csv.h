#pragma once
// What the View panel's CSV export writes: the laps on screen (frozen or live), never a newer lap
// the view has not shown. Oldest lap first, one row per point, each with its lap's receive time.
#include <cstddef>
#include <cstdint>
#include <string>

#include "ui/view/lap_history.h"

namespace ydscope::ui {

// Turns the laps' steady-clock receive times into Unix time, from one reading of both clocks.
struct ReceiveClock {
  std::int64_t steady_now_ns = 0;
  double unix_now_s = 0.0;
  double unix_s(std::int64_t steady_ns) const { return unix_now_s - static_cast<double>(steady_now_ns - steady_ns) * 1e-9; }
};

inline constexpr const char* kLapCsvHeader = "lap,received_unix_s,angle_deg,range_mm,flag\n";

// The newest `laps` of `history` (all it holds when it holds fewer) as CSV with kLapCsvHeader.
std::string shown_laps_csv(const LapHistory& history, std::size_t laps, const ReceiveClock& clock);

}  // namespace ydscope::ui
