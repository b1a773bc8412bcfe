// What is written over the polar view: the status line and its badges (state, health, REC), the
// banner, and when no laps arrive the dimmed cloud with a large overlay saying why.
#include <algorithm>
#include <cfloat>
#include <cstdio>
#include <string>

#include <imgui.h>

#include "ui/panels/panels.h"
#include "ui/view/status/booth_calm.h"
#include "ui/render/theme.h"

namespace ydscope::ui {
namespace {

float status_margin() { return ImGui::GetFontSize() * 0.6f; }

// A rounded pill with text; returns its width so badges can be laid out right to left.
float badge(ImDrawList* draw, ImVec2 top_right, const char* text, ImU32 fill, ImU32 ink) {
  const ImVec2 size = ImGui::CalcTextSize(text);
  const float pad_x = ImGui::GetFontSize() * 0.6f;
  const float pad_y = ImGui::GetFontSize() * 0.25f;
  const ImVec2 lo{top_right.x - size.x - 2.0f * pad_x, top_right.y};
  const ImVec2 hi{top_right.x, top_right.y + size.y + 2.0f * pad_y};
  draw->AddRectFilled(lo, hi, fill, size.y);
  draw->AddText({lo.x + pad_x, lo.y + pad_y}, ink, text);
  return hi.x - lo.x;
}

}  // namespace

ImU32 severity_colour(Severity s) {
  switch (s) {
    case Severity::Ok: return IM_COL32(110, 230, 150, 255);
    case Severity::Info: return IM_COL32(130, 185, 255, 255);
    case Severity::Warning: return IM_COL32(255, 200, 90, 255);
    case Severity::Error: return IM_COL32(255, 105, 95, 255);
  }
  return IM_COL32(255, 255, 255, 255);
}

float status_band_height() { return ImGui::GetTextLineHeight() + 2.0f * status_margin(); }

void draw_view_header(const UiModel& m, float view_left, float view_width) {
  ImDrawList* draw = ImGui::GetForegroundDrawList();
  // The status line sits in its own band at the bottom, which grid labels keep out of.
  const float pad = status_band_height() - status_margin();
  const float line = ImGui::GetTextLineHeightWithSpacing();
  const float bottom = ImGui::GetMainViewport()->WorkSize.y;
  const float wrap = std::max(view_width - 32.0f, 100.0f);
  const SessionSnapshot& s = m.snap;
  const ViewState& v = m.view_state;

  // Status line: model, state in words, measured rate; its colour is the worse of link and health.
  Severity line_severity = v.severity;
  if (!m.alerts.empty()) line_severity = worst(line_severity, m.alerts.front().severity);
  char text[256];
  const char* model = s.device && s.device->profile ? s.device->profile->name.data() : "";
  const auto measured = m.scan_rate.hz();
  int n = std::snprintf(text, sizeof text, "%s%s%s", model, *model ? "  \xE2\x80\xA2  " : "", v.status.c_str());
  if (measured && n > 0 && v.live) {
    std::snprintf(text + n, sizeof text - static_cast<std::size_t>(n),
                  "  \xE2\x80\xA2  %.1f Hz  \xE2\x80\xA2  %zu points", *measured, m.points_in_lap);
  }
  // Lines stack upwards from the status line; each wraps inside the view.
  float y = bottom - pad;
  const auto add_line = [&](const std::string& t, ImU32 colour, bool above) {
    const ImVec2 size = ImGui::CalcTextSize(t.c_str(), nullptr, false, wrap);
    if (above) y -= size.y + (line - ImGui::GetTextLineHeight());
    draw->AddText(ImGui::GetFont(), ImGui::GetFontSize(), {view_left + 16.0f, y}, colour, t.c_str(), nullptr, wrap);
  };
  add_line(text, severity_colour(line_severity), false);
  // The source's own warnings (a recording cut off at its end) stay beside the status line.
  for (auto note = v.notices.rbegin(); note != v.notices.rend(); ++note)
    add_line("warning: " + *note, severity_colour(Severity::Warning), true);
  if (!m.alerts.empty()) {
    std::string alert = m.alerts.front().text;
    if (m.alerts.size() > 1) alert += "  (+" + std::to_string(m.alerts.size() - 1) + " more in Health)";
    add_line(alert, severity_colour(m.alerts.front().severity), true);
  }
  if (!v.live && !v.dim && !s.message.empty()) add_line(s.message, IM_COL32(255, 200, 120, 255), true);
  if (m.paused_view) add_line("frozen (P to resume)", IM_COL32(255, 255, 255, 220), true);
  // Share was asked for and is not on: said until it starts (W tries again).
  if (!m.share.error.empty()) add_line(m.share.error, severity_colour(Severity::Warning), true);

  // Badges in the top-right corner of the view, right to left: REC, SHARED, then health.
  float right = view_left + view_width - 16.0f;
  const float top = 14.0f;
  if (m.recording()) {
    char rec[48];
    std::snprintf(rec, sizeof rec, "\xE2\x80\xA2 REC  %.0f s", std::max(0.0, m.now_s - m.record_started_s));
    right -= badge(draw, {right, top}, rec, IM_COL32(200, 30, 40, 235), IM_COL32(255, 255, 255, 255)) + 10.0f;
  }
  if (m.share.on) {
    char shared[48];
    std::snprintf(shared, sizeof shared, "SHARED  %zu client%s", m.share.clients, m.share.clients == 1 ? "" : "s");
    right -= badge(draw, {right, top}, shared, IM_COL32(30, 90, 170, 235), IM_COL32(255, 255, 255, 255)) + 10.0f;
  }
  if (!m.alerts.empty()) {
    const bool error = m.alerts.front().severity == Severity::Error;
    badge(draw, {right, top}, error ? "HEALTH ERROR" : "HEALTH WARNING",
          error ? IM_COL32(190, 40, 35, 235) : IM_COL32(215, 150, 20, 235),
          error ? IM_COL32(255, 255, 255, 255) : IM_COL32(20, 15, 5, 255));
  }

  const float banner_alpha = banner_opacity(m.now_s - m.banner_since_s, m.booth);
  if (!m.banner.empty() && banner_alpha > 0.0f) {
    const ImVec2 size = ImGui::CalcTextSize(m.banner.c_str(), nullptr, false, wrap - 28.0f);
    const float x = view_left + std::max(16.0f, (view_width - size.x) * 0.5f);
    const float by = std::max(44.0f + (m.recording() || m.share.on || !m.alerts.empty() ? line : 0.0f),
                              source_legend_bottom(m) + 12.0f);
    const auto alpha = [banner_alpha](int a) { return static_cast<ImU32>(static_cast<float>(a) * banner_alpha); };
    draw->AddRectFilled({x - 14.0f, by - 6.0f}, {x + size.x + 14.0f, by + size.y + 6.0f},
                        IM_COL32(22, 45, 80, alpha(215)), 8.0f);
    draw->AddText(ImGui::GetFont(), ImGui::GetFontSize(), {x, by}, IM_COL32(210, 230, 255, alpha(255)),
                  m.banner.c_str(), nullptr, wrap - 28.0f);
  }
}

}  // namespace ydscope::ui
