// The colour legend in a dark box (colour_legend.h says what it holds): in the booth view's large
// type, and in the window's own size over the view's corner, drawn by the same code.
#include <algorithm>

#include <imgui.h>

#include "ui/panels/panels.h"

namespace ydscope::ui {
namespace {

ImU32 im(Rgba8 c) { return IM_COL32(c.r, c.g, c.b, 255); }

}  // namespace

void draw_colour_legend(ImDrawList* draw, ImFont* font, const ColourLegend& legend, float px, ImVec2 bottom_right,
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

void draw_window_legend(const ColourLegend& legend, float view_left, float view_width, float view_height) {
  const float px = ImGui::GetFontSize() * 1.8f;  // its ticks and swatch names in about the window's type
  const float pad = ImGui::GetFontSize() * 0.5f;
  const ImVec2 corner{view_left + view_width - pad, view_height - status_band_height() - pad};
  draw_colour_legend(ImGui::GetBackgroundDrawList(), ImGui::GetFont(), legend, px, corner,
                     std::clamp(view_width * 0.18f, px * 4.0f, px * 7.0f));
}

}  // namespace ydscope::ui
