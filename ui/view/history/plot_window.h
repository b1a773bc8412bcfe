#pragma once
// Which stretch of time the plots show, and how the pointer maps onto it: the last `span` seconds
// up to now while live, or up to the moment of a pause; the wheel zooms about the time under the
// pointer. One window for all the plots of a source, so their time axes line up.
#include <optional>

namespace ydscope::ui {

class PlotWindow {
 public:
  static constexpr double kMinSpanS = 2.0;

  // The shown stretch [start, end] in the app's seconds; `held_s` is how far back the data goes
  // (the full span while not zoomed).
  struct Span {
    double start_s = 0.0;
    double end_s = 0.0;
  };
  Span shown(double now_s, double held_s) const;

  void pause(double now_s) { paused_at_ = now_s; }
  void resume() { paused_at_.reset(); }
  bool paused() const { return paused_at_.has_value(); }
  // The right edge while unzoomed: the pause's moment, or now.
  double end_s(double now_s) const { return paused_at_.value_or(now_s); }
  // Zoom by `factor` (< 1 in, > 1 out) about the time `anchor_s` under the pointer; live, the
  // right edge stays at now. A span wider than the data held goes back to showing all of it.
  void zoom(double factor, double anchor_s, double now_s, double held_s);
  void reset() { span_s_.reset(), end_offset_s_ = 0.0; }
  bool zoomed() const { return span_s_.has_value(); }

 private:
  std::optional<double> paused_at_;
  std::optional<double> span_s_;  // none: everything held
  double end_offset_s_ = 0.0;     // paused: the right edge this far before the pause
};

// The data held, shown in a span of round seconds (2, 3, 4, 5, 6, 8, 10, 12, 15, 20, 25, 30, 40,
// 50, 60, 80, 100, then whole hundreds): while a run starts the plots' scale grows in steps, not
// at every frame.
double round_span_s(double held_s);

// `span` moved back to the last whole one of `columns` pixel columns, each (end - start) / columns
// long: live, a plot then moves a whole column at a time, and between two steps it draws just as
// in the frame before (on a software renderer a frame that repeats the last is not drawn again).
PlotWindow::Span on_whole_columns(PlotWindow::Span span, float columns);

// The pointer's x between the plot's left `x0` and right `x1` edges as a time in `span`, and back.
double time_at_x(float x, float x0, float x1, PlotWindow::Span span);
float x_at_time(double t_s, float x0, float x1, PlotWindow::Span span);

}  // namespace ydscope::ui
