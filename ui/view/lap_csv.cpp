#include "ui/view/lap_csv.h"

#include <algorithm>
#include <cstdio>

namespace ydscope::ui {

std::string shown_laps_csv(const LapHistory& history, std::size_t laps) {
  std::string csv = kLapCsvHeader;
  const std::size_t count = std::min(laps, history.size());
  if (count == 0) return csv;
  const std::int64_t origin_ns = history.at_age(count - 1).first_rx_ns;
  char line[96];
  for (std::size_t age = count; age-- > 0;) {
    const HistoryLap& lap = history.at_age(age);
    const double t_s = static_cast<double>(lap.last_rx_ns - origin_ns) * 1e-9;
    for (const LapPoint& p : lap.points) {
      // 359.99996 would print as 360: the same direction as 0, kept in [0, 360) as the CLI does.
      const auto degrees = static_cast<double>(p.angle_deg);
      std::snprintf(line, sizeof line, "%llu,%.6f,%.4f,%.2f,%u\n", static_cast<unsigned long long>(lap.index), t_s,
                    degrees >= 359.99995 ? 0.0 : degrees, static_cast<double>(p.range_mm), static_cast<unsigned>(p.flag));
      csv += line;
    }
  }
  return csv;
}

}  // namespace ydscope::ui
