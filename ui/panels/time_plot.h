#pragma once
// A small plot of values over time, drawn with ImGui's draw list (Debian's Dear ImGui 1.86 has no
// ImPlot): its title and unit on a line above the data, round ticks on both axes, the events of the
// run as marks on the time axis, and a read-out of the value and time under the pointer. The
// window of time (zoom, pause) is the caller's, shared by the plots of a panel so they line up.
#include <span>

#include <imgui.h>

#include "ui/view/history/metric_history.h"
#include "ui/view/history/plot_events.h"
#include "ui/view/history/plot_window.h"

namespace ydscope::ui {

struct PlotSeries {
  const MetricHistory* values = nullptr;
  const MetricHistory* times = nullptr;  // advancing with values
  ImU32 colour = 0;
  const char* name = "";  // in the read-out beside the value, when the plot has several
  bool bars = false;      // one bar per sample, `bar_s` wide, ending at its time
  float bar_s = 1.0f;
};

struct TimePlotSpec {
  const char* id = "##plot";
  const char* title = "";
  const char* unit = "";        // after the title and each read-out value
  const char* format = "%.1f";  // one value
  bool from_zero = true;        // counts and rates: the value axis starts at 0
  float min_pad = 0.2f;         // see value_range()
  float height = 50.0f;         // the data area, px
  bool time_labels = false;     // the time axis' labels under this plot (the last of a group)
};

struct TimeAxis {
  PlotWindow::Span span;
  double now_s = 0.0;  // labels count back from now
  const PlotEvents* events = nullptr;
};

// Draws one plot as an ImGui item the width of the panel. Returns the time under the pointer when
// the plot is hovered, so the panel can zoom about it.
std::optional<double> draw_time_plot(const TimePlotSpec& spec, std::span<const PlotSeries> series,
                                     const TimeAxis& axis);

// The colour each event is marked in (a stall in red, as the interruption ticks always were).
ImU32 plot_event_colour(PlotEventKind kind);

}  // namespace ydscope::ui
