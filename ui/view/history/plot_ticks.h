#pragma once
// Where a plot's axis ticks go and what range a value axis spans: ticks at steps of 1, 2 or 5
// times a power of ten, so every label is a round number read at a glance, and no more of them
// than the axis has room for. Plain maths for the Plots panel (ui/panels/time_plot.cpp).
#include <array>

namespace ydscope::ui {

struct AxisTicks {
  static constexpr int kMax = 12;
  std::array<double, kMax> at{};  // the ticks inside [lo, hi], lowest first
  int count = 0;
  double step = 0.0;
  int decimals = 0;  // digits after the point that tell two neighbouring ticks apart
};

// At most `max_ticks` (1 to kMax) round ticks inside [lo, hi]; none when the range is empty.
AxisTicks choose_ticks(double lo, double hi, int max_ticks);

struct AxisRange {
  double lo = 0.0;
  double hi = 1.0;
};

// The span a value axis shows for samples between `min` and `max`: counts and rates start at
// zero (`from_zero`); otherwise padded by a fifth each side, at least `min_pad`, so a flat line sits
// mid-plot rather than on an edge.
AxisRange value_range(double min, double max, bool from_zero, double min_pad = 0.2);

}  // namespace ydscope::ui
