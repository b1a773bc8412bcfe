#include "ui/view/history/plot_ticks.h"

#include <algorithm>
#include <cmath>

namespace ydscope::ui {

AxisTicks choose_ticks(double lo, double hi, int max_ticks) {
  AxisTicks ticks;
  max_ticks = std::clamp(max_ticks, 1, AxisTicks::kMax);
  if (!(hi > lo) || !std::isfinite(lo) || !std::isfinite(hi)) return ticks;
  // The smallest 1-2-5 step that leaves at most max_ticks inside the range.
  const double rough = (hi - lo) / max_ticks;
  const auto fits = [&](double step) { return std::floor(hi / step) - std::ceil(lo / step) + 1 <= max_ticks; };
  double step = 0.0;
  for (double power = std::pow(10.0, std::floor(std::log10(rough))); step == 0.0; power *= 10.0)
    for (const double m : {1.0, 2.0, 5.0})
      if (fits(m * power)) {
        step = m * power;
        break;
      }
  ticks.step = step;
  ticks.decimals = step >= 1.0 ? 0 : static_cast<int>(std::ceil(-std::log10(step) - 1e-9));
  for (double k = std::ceil(lo / step); k * step <= hi + step * 1e-9 && ticks.count < AxisTicks::kMax; k += 1.0) {
    const double v = k * step;
    ticks.at[static_cast<std::size_t>(ticks.count++)] = std::abs(v) < step * 1e-9 ? 0.0 : v;  // no "-0"
  }
  return ticks;
}

AxisRange value_range(double min, double max, bool from_zero, double min_pad) {
  if (max < min) std::swap(min, max);
  if (from_zero) return {std::min(0.0, min), std::max({max * 1.15, min_pad, 1.0})};
  const double pad = std::max((max - min) * 0.2, min_pad);
  return {min - pad, max + pad};
}

}  // namespace ydscope::ui
