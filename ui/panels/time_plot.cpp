// The Plots panel's plot widget (time_plot.h). Nothing here allocates per frame: text goes through
// stack buffers, and a line is drawn at most one segment per pixel column however many samples
// fall into it, so a zoomed-out plot of minutes costs what a plot of seconds does.
#include "ui/panels/time_plot.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>

#include "ui/panels/plot_palette.h"
#include "ui/view/history/plot_readout.h"
#include "ui/view/history/plot_ticks.h"

namespace ydscope::ui {
namespace {

struct Frame {
  ImVec2 lo, hi;  // the data area
  AxisRange values;
  PlotWindow::Span span;
  float x(double t) const { return x_at_time(t, lo.x, hi.x, span); }
  float y(double v) const {
    const double t = std::clamp((v - values.lo) / (values.hi - values.lo), 0.0, 1.0);
    return hi.y - static_cast<float>(t) * (hi.y - lo.y);
  }
};

// The lowest and highest value shown in the span, over every series.
AxisRange shown_values(std::span<const PlotSeries> series, PlotWindow::Span span) {
  double lo = std::numeric_limits<double>::infinity(), hi = -lo;
  for (const PlotSeries& s : series) {
    const std::size_t n = std::min(s.times->size(), s.values->size());
    for (std::size_t i = first_at_or_after(*s.times, span.start_s); i < n && s.times->at(i) <= span.end_s; ++i) {
      lo = std::min(lo, static_cast<double>(s.values->at(i)));
      hi = std::max(hi, static_cast<double>(s.values->at(i)));
    }
  }
  if (lo > hi) lo = hi = 0.0;
  return {lo, hi};
}

// One segment per pixel column: samples that share a column become one vertical stroke.
void draw_line(ImDrawList* draw, const Frame& f, const PlotSeries& s) {
  const std::size_t n = std::min(s.times->size(), s.values->size());
  std::size_t i = first_at_or_after(*s.times, f.span.start_s);
  if (i > 0) --i;  // from the sample before the window, so the line enters from the edge
  bool have = false;
  ImVec2 prev{};
  float column = 0.0f, column_lo = 0.0f, column_hi = 0.0f;
  for (; i < n; ++i) {
    const ImVec2 p{f.x(s.times->at(i)), f.y(s.values->at(i))};
    if (have && std::floor(p.x) == column) {
      column_lo = std::min(column_lo, p.y), column_hi = std::max(column_hi, p.y);
      prev = p;
      continue;
    }
    if (have) {
      if (column_hi - column_lo > 1.0f) draw->AddLine({prev.x, column_lo}, {prev.x, column_hi}, s.colour, 1.5f);
      draw->AddLine(prev, p, s.colour, 1.5f);
    }
    have = true;
    prev = p;
    column = std::floor(p.x), column_lo = column_hi = p.y;
    if (s.times->at(i) > f.span.end_s) break;  // one past the window, then done
  }
  if (have && column_hi - column_lo > 1.0f) draw->AddLine({prev.x, column_lo}, {prev.x, column_hi}, s.colour, 1.5f);
}

void draw_bars(ImDrawList* draw, const Frame& f, const PlotSeries& s, int slot, int slots) {
  const std::size_t n = std::min(s.times->size(), s.values->size());
  const float base = f.y(std::max(f.values.lo, 0.0));
  for (std::size_t i = first_at_or_after(*s.times, f.span.start_s); i < n && s.times->at(i) <= f.span.end_s; ++i) {
    if (s.values->at(i) <= 0.0f) continue;
    const float x1 = f.x(s.times->at(i)), x0 = f.x(s.times->at(i) - s.bar_s);
    const float w = std::max((x1 - x0) / static_cast<float>(slots), 1.0f);
    const float left = x0 + w * static_cast<float>(slot);
    draw->AddRectFilled({left, f.y(s.values->at(i))}, {left + std::max(w - 1.0f, 1.0f), base}, s.colour);
  }
}

// "12.5" with the decimals the ticks need; ten thousand and more in thousands ("40k"), so every
// label fits the one column width all plots share.
void tick_text(char* out, std::size_t size, double v, int decimals) {
  if (std::abs(v) >= 10'000.0)
    std::snprintf(out, size, "%.0fk", v / 1000.0);
  else
    std::snprintf(out, size, "%.*f", decimals, v);
}

}  // namespace

ImU32 plot_event_colour(PlotEventKind kind) {
  switch (kind) {
    case PlotEventKind::Stall: return IM_COL32(255, 90, 80, 230);
    case PlotEventKind::Reconnect: return IM_COL32(255, 190, 60, 230);
    case PlotEventKind::RateChange: return IM_COL32(120, 200, 255, 230);
    case PlotEventKind::HealthChange: return IM_COL32(220, 120, 255, 230);
  }
  return IM_COL32(200, 200, 200, 230);
}

std::optional<double> draw_time_plot(const TimePlotSpec& spec, std::span<const PlotSeries> series,
                                     const TimeAxis& axis) {
  ImDrawList* draw = ImGui::GetWindowDrawList();
  const float font = ImGui::GetFontSize();
  const float line_h = ImGui::GetTextLineHeight() + 2.0f;
  const ImVec2 top = ImGui::GetCursorScreenPos();
  const float width = std::max(ImGui::GetContentRegionAvail().x, 8.0f * font);

  // The data area's edges first, since the span steps by its whole pixel columns; the value
  // labels' column is one width for every plot, so their time axes line up.
  char text[96];
  const float label_w = ImGui::CalcTextSize("0000").x;
  Frame f;
  f.lo = {top.x + label_w + 6.0f, top.y + line_h};
  f.hi = {top.x + width - 2.0f, f.lo.y + spec.height};
  f.span = on_whole_columns(axis.span, std::floor(f.hi.x - f.lo.x));
  const double now_s = axis.now_s - (axis.span.end_s - f.span.end_s);  // moved with the span
  const AxisRange seen = shown_values(series, f.span);
  f.values = value_range(seen.lo, seen.hi, spec.from_zero, spec.min_pad);
  const AxisTicks value_ticks =
      choose_ticks(f.values.lo, f.values.hi, std::max(2, static_cast<int>(spec.height / (font * 0.95f))));
  const float total_h = line_h + spec.height + (spec.time_labels ? line_h : 4.0f);
  ImGui::InvisibleButton(spec.id, {width, total_h});
  const bool hovered = ImGui::IsItemHovered();
  const ImVec2 mouse = ImGui::GetIO().MousePos;

  // The frame, the value grid and its labels (left of the data, never on it).
  draw->AddRectFilled(f.lo, f.hi, plot_palette::kFrame, 2.0f);
  for (int k = 0; k < value_ticks.count; ++k) {
    const double v = value_ticks.at[static_cast<std::size_t>(k)];
    const float y = f.y(v);
    draw->AddLine({f.lo.x, y}, {f.hi.x, y}, plot_palette::kGrid);
    tick_text(text, sizeof text, v, value_ticks.decimals);
    const ImVec2 size = ImGui::CalcTextSize(text);
    const float ty = std::clamp(y - size.y * 0.5f, f.lo.y - 2.0f, f.hi.y - size.y + 2.0f);
    draw->AddText({f.lo.x - 4.0f - size.x, ty}, plot_palette::kTickText, text);
  }
  // The time axis: ticks counted back from now, labelled under the last plot of a group.
  const AxisTicks time_ticks = choose_ticks(f.span.start_s - now_s, f.span.end_s - now_s,
                                            std::max(2, static_cast<int>((f.hi.x - f.lo.x) / (font * 4.0f))));
  for (int k = 0; k < time_ticks.count; ++k) {
    const double ago = time_ticks.at[static_cast<std::size_t>(k)];
    const float x = f.x(now_s + ago);
    draw->AddLine({x, f.lo.y}, {x, f.hi.y}, plot_palette::kGrid);
    if (!spec.time_labels) continue;
    if (ago == 0.0)
      std::snprintf(text, sizeof text, "now");
    else
      std::snprintf(text, sizeof text, "%.*f s", time_ticks.decimals, ago);
    const float w = ImGui::CalcTextSize(text).x;
    draw->AddText({std::clamp(x - w * 0.5f, f.lo.x - label_w, f.hi.x - w), f.hi.y + 1.0f}, plot_palette::kTickText,
                  text);
  }

  // The data, clipped to the frame, then the events over it.
  draw->PushClipRect(f.lo, f.hi, true);
  int bar_slots = 0;
  for (const PlotSeries& s : series) bar_slots += s.bars ? 1 : 0;
  int bar_slot = 0;
  for (const PlotSeries& s : series) {
    if (s.bars)
      draw_bars(draw, f, s, bar_slot++, bar_slots);
    else
      draw_line(draw, f, s);
  }
  const PlotEvent* event_under = nullptr;
  if (axis.events) {
    for (std::size_t i = 0; i < axis.events->size(); ++i) {
      const PlotEvent& e = axis.events->at(i);
      if (e.time_s < f.span.start_s || e.time_s > f.span.end_s) continue;
      const float x = f.x(e.time_s);
      draw->AddLine({x, f.lo.y}, {x, f.hi.y}, plot_event_colour(e.kind), 2.0f);
      draw->AddTriangleFilled({x - 4.0f, f.hi.y}, {x + 4.0f, f.hi.y}, {x, f.hi.y - 6.0f}, plot_event_colour(e.kind));
      if (hovered && std::abs(mouse.x - x) <= 4.0f) event_under = &e;
    }
  }

  draw->PopClipRect();
  // The title line: what and in which unit on the left, the newest value or the read-out on the right.
  std::snprintf(text, sizeof text, spec.unit[0] ? "%s (%s)" : "%s", spec.title, spec.unit);
  draw->AddText(top, ImGui::GetColorU32(ImGuiCol_TextDisabled), text);
  char reading[160] = "";
  std::size_t used = 0;
  const auto append = [&](const char* format, auto... args) {
    if (used < sizeof reading)
      used += static_cast<std::size_t>(std::snprintf(reading + used, sizeof reading - used, format, args...));
  };
  std::optional<double> pointer_time;
  if (hovered && mouse.x >= f.lo.x && mouse.x <= f.hi.x) {
    const double t = time_at_x(mouse.x, f.lo.x, f.hi.x, f.span);
    pointer_time = t;
    draw->AddLine({mouse.x, f.lo.y}, {mouse.x, f.hi.y}, plot_palette::kCursor);
    const double gap = std::max((f.span.end_s - f.span.start_s) * 0.03, 0.6);
    for (const PlotSeries& s : series) {
      const auto r = read_at(*s.times, *s.values, t, gap);
      if (!r) continue;
      draw->AddCircleFilled({f.x(r->time_s), f.y(r->value)}, 3.0f, s.colour);
      char value[32];
      std::snprintf(value, sizeof value, spec.format, static_cast<double>(r->value));
      append(series.size() > 1 && s.name[0] ? "%s %s  " : "%s%s  ", s.name, value);
    }
    append("at %.1f s", t - now_s);
    if (event_under) append(", %s", plot_event_name(event_under->kind));
  } else {
    for (const PlotSeries& s : series) {
      const std::size_t n = std::min(s.times->size(), s.values->size());
      if (n == 0) continue;
      char value[32];
      std::snprintf(value, sizeof value, spec.format, static_cast<double>(s.values->at(n - 1)));
      append(series.size() > 1 && s.name[0] ? "%s %s  " : "%s%s  ", s.name, value);
    }
    if (used == 0) append("waiting");
  }
  const float reading_w = ImGui::CalcTextSize(reading).x;
  draw->AddText({std::max(top.x + width - reading_w - 2.0f, top.x + ImGui::CalcTextSize(text).x + font), top.y},
                ImGui::GetColorU32(ImGuiCol_Text), reading);
  return pointer_time;
}

}  // namespace ydscope::ui
