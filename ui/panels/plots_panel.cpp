// Plots: the run over time, where a trend or a spike is seen at a glance rather than read.
#include <algorithm>
#include <cstdio>

#include <imgui.h>

#include "ui/panels/panels.h"

namespace ydscope::ui {
namespace {

constexpr float kPlotHeight = 54.0f;
const ImVec4 kQuiet{0.55f, 0.6f, 0.68f, 1.0f};
const ImVec4 kWarn{1.0f, 0.6f, 0.35f, 1.0f};

// x of sample i of n across the plot's inner frame, as PlotLines places it.
float sample_x(const ImVec2& lo, const ImVec2& hi, std::size_t i, std::size_t n) {
  const float pad = ImGui::GetStyle().FramePadding.x;
  const float t = n > 1 ? static_cast<float>(i) / static_cast<float>(n - 1) : 0.0f;
  return lo.x + pad + t * (hi.x - lo.x - 2 * pad);
}

float sample_y(const ImVec2& lo, const ImVec2& hi, float value, float y_min, float y_max) {
  const float pad = ImGui::GetStyle().FramePadding.y;
  const float t = std::clamp((value - y_min) / (y_max - y_min), 0.0f, 1.0f);
  return hi.y - pad - t * (hi.y - lo.y - 2 * pad);
}

void plot_lines(const char* id, const MetricHistory& h, const char* overlay, float y_min, float y_max) {
  ImGui::PlotLines(id, h.data(), static_cast<int>(h.size()), static_cast<int>(h.offset()), overlay, y_min, y_max,
                   {0.0f, kPlotHeight});
}

// A red tick across the plot just drawn wherever `breaks` holds 1: an interruption, so a line that
// runs on across it is not read as the motor slowing.
void mark_breaks(const MetricHistory& breaks) {
  const ImVec2 a = ImGui::GetItemRectMin(), b = ImGui::GetItemRectMax();
  ImDrawList* draw = ImGui::GetWindowDrawList();
  const std::size_t n = breaks.size();
  for (std::size_t i = 0; i < n; ++i) {
    if (breaks.data()[(breaks.offset() + i) % n] < 0.5f) continue;
    const float x = sample_x(a, b, i, n);
    draw->AddLine({x, a.y + 1.0f}, {x, b.y - 1.0f}, IM_COL32(255, 90, 80, 230), 2.0f);
  }
}

// Measured scan rate per lap with the set value drawn over it as a second (green) line.
void scan_rate_plot(const RunPlots& plots) {
  const MetricHistory& measured = plots.measured_hz();
  const MetricHistory& set = plots.set_hz();
  char overlay[96] = "scan rate: waiting for laps";
  float lo = 0.0f, hi = 1.0f;
  if (const auto now = measured.last()) {
    lo = std::min(measured.min(), set.min());
    hi = std::max(measured.max(), set.max());
    const float pad = std::max((hi - lo) * 0.2f, 0.2f);  // a flat line sits mid-plot, not on an edge
    lo -= pad, hi += pad;
    std::snprintf(overlay, sizeof overlay, "measured %.2f Hz, set %.2f Hz", *now, set.last().value_or(*now));
  }
  plot_lines("##scan_rate", measured, overlay, lo, hi);
  mark_breaks(plots.rate_breaks());
  const ImVec2 a = ImGui::GetItemRectMin(), b = ImGui::GetItemRectMax();
  ImDrawList* draw = ImGui::GetWindowDrawList();
  const std::size_t n = set.size();
  for (std::size_t i = 1; i < n; ++i) {
    const float v0 = set.data()[(set.offset() + i - 1) % n], v1 = set.data()[(set.offset() + i) % n];
    draw->AddLine({sample_x(a, b, i - 1, n), sample_y(a, b, v0, lo, hi)},
                  {sample_x(a, b, i, n), sample_y(a, b, v1, lo, hi)}, IM_COL32(90, 210, 120, 200), 1.5f);
  }
  ImGui::PushTextWrapPos(0.0f);
  ImGui::TextDisabled("last %zu laps: blue measured, green set, red an interruption", n);
  ImGui::PopTextWrapPos();
}

void value_plot(const char* id, const MetricHistory& h, const char* format, const char* what) {
  char overlay[96];
  if (const auto now = h.last())
    std::snprintf(overlay, sizeof overlay, format, *now);
  else
    std::snprintf(overlay, sizeof overlay, "%s: waiting", what);
  const float hi = std::max(h.max() * 1.15f, 1.0f);
  plot_lines(id, h, overlay, 0.0f, hi);
}

// Errors per second as bars; orange once any has arrived in the window, so a burst stays visible.
void error_plot(const char* id, const MetricHistory& h, const char* what) {
  const bool any = h.max() > 0.0f;
  char overlay[96];
  std::snprintf(overlay, sizeof overlay, "%s/s: now %.0f, worst %.0f", what, h.last().value_or(0.0f), h.max());
  ImGui::PushStyleColor(ImGuiCol_PlotHistogram, any ? kWarn : kQuiet);
  ImGui::PlotHistogram(id, h.data(), static_cast<int>(h.size()), static_cast<int>(h.offset()), overlay, 0.0f,
                       std::max(h.max() * 1.15f, 1.0f), {0.0f, kPlotHeight * 0.7f});
  ImGui::PopStyleColor();
}

}  // namespace

void draw_plots_panel(const UiModel& m) {
  if (!ImGui::CollapsingHeader("Plots", ImGuiTreeNodeFlags_DefaultOpen)) return;
  const RunPlots& p = m.plots;
  // ImGui 1.86's plots take their width from the item width (a negative frame width is not read).
  ImGui::PushItemWidth(-1.0f);
  scan_rate_plot(p);
  value_plot("##points", p.points(), "%.0f points per lap", "points per lap");
  mark_breaks(p.per_lap_breaks());
  value_plot("##latency", p.latency_ms(), "lap to screen %.1f ms", "latency");
  value_plot("##bytes", p.bytes_per_s(), "%.0f bytes/s", "bytes/s");
  error_plot("##checksum", p.checksum_errors_per_s(), "checksum errors");
  error_plot("##crc8", p.crc8_failures_per_s(), "CRC8 failures");
  ImGui::PopItemWidth();
  ImGui::PushTextWrapPos(0.0f);  // wrapped at the panel's edge, never cut off
  ImGui::TextDisabled("per lap (top three), per second over the last %zu s (the rest)", RunPlots::kSeconds);
  ImGui::PopTextWrapPos();
}

}  // namespace ydscope::ui
