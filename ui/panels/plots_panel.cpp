// Plots: the run over time, where a trend or a spike is seen at a glance rather than read. All
// plots share one time axis (zoomed with the wheel, paused with a button), so a step in one lines
// up with a stall, a reconnect, a scan-rate change or a health change marked on every one.
#include <algorithm>
#include <array>
#include <cmath>

#include <imgui.h>

#include "ui/panels/panels.h"
#include "ui/panels/plot_palette.h"
#include "ui/panels/time_plot.h"

namespace ydscope::ui {
namespace {

// What each event mark's colour means, in the marks' own colours.
void event_key() {
  for (const PlotEventKind kind :
       {PlotEventKind::Stall, PlotEventKind::Reconnect, PlotEventKind::RateChange, PlotEventKind::HealthChange}) {
    ImGui::TextColored(ImGui::ColorConvertU32ToFloat4(plot_event_colour(kind)), "%s", plot_event_name(kind));
    if (kind != PlotEventKind::HealthChange) ImGui::SameLine();
  }
}

}  // namespace

void draw_plots_panel(const UiModel& m, PanelEdits& e) {
  if (!ImGui::CollapsingHeader("Plots", ImGuiTreeNodeFlags_DefaultOpen)) return;
  PlotWindow& window = e.plot_window;
  if (ImGui::SmallButton(window.paused() ? "live" : "pause")) {
    if (window.paused()) {
      window.resume();
      window.reset();
    } else {
      e.paused_plots = m.plots;  // the plots stay as they were, however long the pause
      window.pause(m.now_s);
    }
  }
  ImGui::SameLine();
  ImGui::TextDisabled(window.paused() ? "paused: wheel zooms, double-click shows all"
                                      : "wheel zooms, double-click shows all");
  const RunPlots& p = window.paused() ? e.paused_plots : m.plots;
  const double end_s = window.end_s(m.now_s);
  const double held_s =
      std::clamp(round_span_s(p.held_s(end_s)), PlotWindow::kMinSpanS, static_cast<double>(RunPlots::kSeconds));
  const TimeAxis axis{window.shown(m.now_s, held_s), end_s, &p.events()};
  const float h = ImGui::GetFontSize() * 2.9f;

  std::optional<double> pointer;
  const auto plot = [&](const TimePlotSpec& spec, auto&&... series) {
    const std::array<PlotSeries, sizeof...(series)> list{series...};
    if (const auto t = draw_time_plot(spec, list, axis)) pointer = t;
  };
  plot(TimePlotSpec{"##scan_rate", "scan rate", "Hz", "%.2f", false, 0.2f, h, false},
       PlotSeries{&p.measured_hz(), &p.rate_times(), plot_palette::kMeasured, "measured"},
       PlotSeries{&p.set_hz(), &p.rate_times(), plot_palette::kSet, "set"});
  plot(TimePlotSpec{"##points", "points per lap", "", "%.0f", true, 0.2f, h, false},
       PlotSeries{&p.points(), &p.lap_times(), plot_palette::kValue});
  plot(TimePlotSpec{"##latency", "lap to screen", "ms", "%.1f", true, 0.2f, h, false},
       PlotSeries{&p.latency_ms(), &p.latency_times(), plot_palette::kValue});
  plot(TimePlotSpec{"##bytes", "received", "bytes/s", "%.0f", true, 0.2f, h, false},
       PlotSeries{&p.bytes_per_s(), &p.second_times(), plot_palette::kValue});
  plot(TimePlotSpec{"##errors", "errors", "per s", "%.0f", true, 0.2f, h * 0.7f, true},
       PlotSeries{&p.checksum_errors_per_s(), &p.second_times(), plot_palette::kChecksum, "checksum", true},
       PlotSeries{&p.crc8_failures_per_s(), &p.second_times(), plot_palette::kCrc8, "CRC8", true});
  event_key();

  if (pointer) {
    const float wheel = ImGui::GetIO().MouseWheel;
    if (wheel != 0.0f) window.zoom(std::pow(0.8, static_cast<double>(wheel)), *pointer, m.now_s, held_s);
    if (ImGui::IsMouseDoubleClicked(ImGuiMouseButton_Left)) window.reset();
  }
}

}  // namespace ydscope::ui
