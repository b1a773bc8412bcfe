#include "ui/view/history/plot_window.h"

#include <algorithm>
#include <cmath>

namespace ydscope::ui {

PlotWindow::Span PlotWindow::shown(double now_s, double held_s) const {
  const double end = paused_at_ ? *paused_at_ - end_offset_s_ : now_s;
  const double span = std::max(span_s_.value_or(held_s), kMinSpanS);
  return {end - span, end};
}

void PlotWindow::zoom(double factor, double anchor_s, double now_s, double held_s) {
  const Span was = shown(now_s, held_s);
  const double span = std::max((was.end_s - was.start_s) * factor, kMinSpanS);
  if (span >= held_s) {
    reset();
    return;
  }
  span_s_ = span;
  if (!paused_at_) return;  // live: the right edge is now
  // Paused: the time under the pointer stays under it, and the right edge never passes the pause.
  const double end = anchor_s + (was.end_s - anchor_s) * factor;
  end_offset_s_ = std::clamp(*paused_at_ - end, 0.0, std::max(held_s - span, 0.0));
}

double round_span_s(double held_s) {
  static constexpr double kRound[] = {2, 3, 4, 5, 6, 8, 10, 12, 15, 20, 25, 30, 40, 50, 60, 80, 100};
  for (const double span : kRound)
    if (held_s <= span) return span;
  return std::ceil(held_s / 100.0) * 100.0;
}

PlotWindow::Span on_whole_columns(PlotWindow::Span span, float columns) {
  const double width = span.end_s - span.start_s;
  if (!(columns >= 1.0f) || !(width > 0.0)) return span;
  const double column = width / static_cast<double>(columns);
  const double end = std::floor(span.end_s / column) * column;
  return {end - width, end};
}

double time_at_x(float x, float x0, float x1, PlotWindow::Span span) {
  if (x1 <= x0) return span.end_s;
  const double t = std::clamp(static_cast<double>(x - x0) / static_cast<double>(x1 - x0), 0.0, 1.0);
  return span.start_s + t * (span.end_s - span.start_s);
}

float x_at_time(double t_s, float x0, float x1, PlotWindow::Span span) {
  const double width = span.end_s - span.start_s;
  if (width <= 0.0) return x1;
  return x0 + static_cast<float>((t_s - span.start_s) / width) * (x1 - x0);
}

}  // namespace ydscope::ui
