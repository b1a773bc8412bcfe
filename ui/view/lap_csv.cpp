#include "ui/view/lap_csv.h"

#include <algorithm>
#include <cstdio>

namespace ydscope::ui {

std::string shown_laps_csv(const LapHistory& history, std::size_t laps, const ReceiveClock& clock) {
  std::string csv = kLapCsvHeader;
  const std::size_t count = std::min(laps, history.size());
  char line[96];
  for (std::size_t age = count; age-- > 0;) {
    const HistoryLap& lap = history.at_age(age);
    const double received = clock.unix_s(lap.last_rx_ns);
    for (const LapPoint& p : lap.points) {
      std::snprintf(line, sizeof line, "%llu,%.3f,%.3f,%.1f,%u\n", static_cast<unsigned long long>(lap.index), received,
                    static_cast<double>(p.angle_deg), static_cast<double>(p.range_mm), static_cast<unsigned>(p.flag));
      csv += line;
    }
  }
  return csv;
}

}  // namespace ydscope::ui
