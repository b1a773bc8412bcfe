#include "ui/view/export/lap_csv.h"

#include <algorithm>

namespace ydscope::ui {

std::string shown_laps_csv(const LapHistory& history, std::size_t laps) {
  std::string csv = kLapCsvHeader;
  const std::size_t count = std::min(laps, history.size());
  if (count == 0) return csv;
  const std::int64_t origin_ns = history.at_age(count - 1).first_rx_ns;
  for (std::size_t age = count; age-- > 0;) {
    const HistoryLap& lap = history.at_age(age);
    append_lap_csv_rows(csv, lap.index, static_cast<double>(lap.last_rx_ns - origin_ns) * 1e-9, lap.points);
  }
  return csv;
}

}  // namespace ydscope::ui
