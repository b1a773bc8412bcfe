#include "ui/view/history/plot_readout.h"

#include <cmath>

namespace ydscope::ui {

std::size_t first_at_or_after(const MetricHistory& times, double t_s) {
  std::size_t lo = 0, hi = times.size();
  while (lo < hi) {
    const std::size_t mid = (lo + hi) / 2;
    if (times.at(mid) < t_s)
      lo = mid + 1;
    else
      hi = mid;
  }
  return lo;
}

std::optional<PlotReading> read_at(const MetricHistory& times, const MetricHistory& values, double t_s,
                                   double max_gap_s) {
  const std::size_t n = std::min(times.size(), values.size());
  if (n == 0) return std::nullopt;
  std::size_t i = std::min(first_at_or_after(times, t_s), n - 1);
  if (i > 0 && std::abs(times.at(i - 1) - t_s) < std::abs(times.at(i) - t_s)) --i;
  if (std::abs(times.at(i) - t_s) > max_gap_s) return std::nullopt;
  return PlotReading{i, times.at(i), values.at(i)};
}

}  // namespace ydscope::ui
