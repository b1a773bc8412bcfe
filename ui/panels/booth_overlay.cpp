// The booth view (full screen): large type scaled to the screen, legible from across a stand, with
// what is shown (model, state, scan rate, points per second) and what the colours mean; the stand's
// own title line and a large live figure (visitors, the nearest one) when settings ask for them.
#include <algorithm>
#include <cstdio>
#include <string>

#include <imgui.h>

#include "ui/panels/panels.h"
#include "ui/render/theme.h"

namespace ydscope::ui {
namespace {

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

}  // namespace

void draw_booth_overlay(const UiModel& m, float view_left, float view_width, float view_height) {
  ImDrawList* draw = ImGui::GetForegroundDrawList();
  ImFont* font = display_font() ? display_font() : ImGui::GetFont();
  const float px = booth_text_px(view_height);
  const float pad = px * 0.6f;
  const SessionSnapshot& s = m.snap;

  // Top: the stand's title across the middle, the live figure at the right.
  float y = pad;
  if (!m.booth_title.empty()) {
    const float w = font->CalcTextSizeA(px * 1.1f, 1e9f, 0.0f, m.booth_title.c_str()).x;
    draw->AddText(font, px * 1.1f, {view_left + std::max((view_width - w) * 0.5f, pad), y},
                  IM_COL32(245, 247, 252, 255), m.booth_title.c_str());
    y += px * 1.5f;
  }
  if (!m.booth_figure.empty()) {
    const float w = font->CalcTextSizeA(px * 1.6f, 1e9f, 0.0f, m.booth_figure.c_str()).x;
    draw->AddText(font, px * 1.6f, {view_left + view_width - pad - w, y}, IM_COL32(255, 196, 92, 255),
                  m.booth_figure.c_str());
  }

  // Top left, under the title: the model and its state, then the rates.
  const std::string model = s.device && s.device->profile ? std::string(s.device->profile->name) : std::string("lidar");
  const ImU32 state_colour = severity_colour(m.view_state.severity);
  float x = view_left + pad;
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
  draw_colour_legend(draw, font, m.legend, px, corner, std::clamp(view_width * 0.22f, px * 5.0f, view_width * 0.4f));
}

}  // namespace ydscope::ui
