// The booth view (full screen): large type scaled to the screen, legible from across a stand, with
// what is shown (model, state, scan rate, points per second) and what the colours mean.
#include <algorithm>
#include <cstdio>
#include <string>

#include <imgui.h>

#include "ui/panels/panels.h"
#include "ui/render/theme.h"

namespace ydscope::ui {
namespace {

ImU32 im(Rgba8 c) { return IM_COL32(c.r, c.g, c.b, 255); }

// "9,000": thousands apart, read at a glance.
std::string grouped(long n) {
  const std::string digits = std::to_string(n);
  std::string out;
  for (std::size_t i = 0; i < digits.size(); ++i) {
    if (i > 0 && (digits.size() - i) % 3 == 0) out += ',';
    out += digits[i];
  }
  return out;
}

void draw_legend(ImDrawList* draw, ImFont* font, const ColourLegend& legend, float px, ImVec2 bottom_right,
                 float bar_width) {
  const float title_px = px * 0.55f;
  const float tick_px = px * 0.5f;
  const float pad = px * 0.45f;
  const float bar_h = px * 0.4f;
  float content_w = bar_width;
  float content_h = title_px + pad * 0.5f;
  if (!legend.bar.empty()) {
    content_h += bar_h + pad * 0.3f + tick_px;
  } else {
    content_w = 0.0f;
    for (const LegendSwatch& s : legend.swatches)
      content_w = std::max(content_w, tick_px * 1.4f + font->CalcTextSizeA(tick_px, 1e9f, 0.0f, s.text.c_str()).x);
    content_h += static_cast<float>(legend.swatches.size()) * tick_px * 1.3f;
  }
  const ImVec2 lo{bottom_right.x - content_w - 2.0f * pad, bottom_right.y - content_h - 2.0f * pad};
  draw->AddRectFilled(lo, bottom_right, IM_COL32(12, 15, 21, 240), pad * 0.6f);
  float y = lo.y + pad;
  const float x = lo.x + pad;
  draw->AddText(font, title_px, {x, y}, IM_COL32(200, 208, 222, 255), legend.title.c_str());
  y += title_px + pad * 0.5f;
  if (!legend.bar.empty()) {
    const float step = bar_width / static_cast<float>(legend.bar.size() - 1);
    for (std::size_t i = 0; i + 1 < legend.bar.size(); ++i) {
      const float x0 = x + step * static_cast<float>(i);
      draw->AddRectFilledMultiColor({x0, y}, {x0 + step + 0.5f, y + bar_h}, im(legend.bar[i]), im(legend.bar[i + 1]),
                                    im(legend.bar[i + 1]), im(legend.bar[i]));
    }
    y += bar_h + pad * 0.3f;
    for (const LegendTick& t : legend.ticks) {
      const float w = font->CalcTextSizeA(tick_px, 1e9f, 0.0f, t.text.c_str()).x;
      // Centred under its place, kept inside the bar's ends.
      const float tx = std::clamp(x + t.at * bar_width - w * 0.5f, x, x + bar_width - w);
      draw->AddLine({x + t.at * bar_width, y - pad * 0.3f}, {x + t.at * bar_width, y - pad * 0.05f},
                    IM_COL32(220, 225, 235, 255), 2.0f);
      draw->AddText(font, tick_px, {tx, y}, IM_COL32(225, 230, 240, 255), t.text.c_str());
    }
  } else {
    for (const LegendSwatch& s : legend.swatches) {
      draw->AddCircleFilled({x + tick_px * 0.45f, y + tick_px * 0.55f}, tick_px * 0.35f, im(s.colour), 20);
      draw->AddText(font, tick_px, {x + tick_px * 1.4f, y}, IM_COL32(225, 230, 240, 255), s.text.c_str());
      y += tick_px * 1.3f;
    }
  }
}

}  // namespace

void draw_booth_overlay(const UiModel& m, float view_left, float view_width, float view_height) {
  ImDrawList* draw = ImGui::GetForegroundDrawList();
  ImFont* font = display_font() ? display_font() : ImGui::GetFont();
  const float px = booth_text_px(view_height);
  const float pad = px * 0.6f;
  const SessionSnapshot& s = m.snap;

  // Top left: the model and its state, then the rates.
  const std::string model = s.device && s.device->profile ? std::string(s.device->profile->name) : std::string("lidar");
  const ImU32 state_colour = severity_colour(m.view_state.severity);
  float x = view_left + pad;
  float y = pad;
  draw->AddText(font, px, {x, y}, IM_COL32(245, 247, 252, 255), model.c_str());
  const float model_w = font->CalcTextSizeA(px, 1e9f, 0.0f, model.c_str()).x;
  draw->AddText(font, px * 0.7f, {x + model_w + px * 0.5f, y + px * 0.25f}, state_colour, m.view_state.status.c_str());
  y += px * 1.15f;
  if (const auto hz = m.scan_rate.hz(); hz && m.view_state.live) {
    char rates[96];
    std::snprintf(rates, sizeof rates, "%.1f Hz   %s points/s", *hz,
                  grouped(std::lround(*hz * static_cast<double>(m.points_in_lap))).c_str());
    draw->AddText(font, px * 0.7f, {x, y}, IM_COL32(210, 216, 228, 255), rates);
  }

  // Bottom right, above the status line: what the colours mean.
  const ImVec2 corner{view_left + view_width - pad, view_height - status_band_height() - pad * 0.5f};
  draw_legend(draw, font, m.legend, px, corner, std::clamp(view_width * 0.22f, px * 5.0f, view_width * 0.4f));
}

}  // namespace ydscope::ui
