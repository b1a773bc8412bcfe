#pragma once
// The cursor read-out of a plot: the sample nearest in time to the pointer, with its value and
// time, found by bisection over the sample times (which only grow), so hovering costs nothing.
#include <cstddef>
#include <optional>

#include "ui/view/history/metric_history.h"

namespace ydscope::ui {

struct PlotReading {
  std::size_t index = 0;  // oldest first
  double time_s = 0.0;
  float value = 0.0f;
};

// `times` and `values` advance together; none when no sample lies within `max_gap_s` of `t_s`.
std::optional<PlotReading> read_at(const MetricHistory& times, const MetricHistory& values, double t_s,
                                   double max_gap_s);

// The first sample (oldest first) at or after `t_s`: where a plot starts drawing its window.
std::size_t first_at_or_after(const MetricHistory& times, double t_s);

}  // namespace ydscope::ui
