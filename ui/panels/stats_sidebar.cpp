// Statistics, the sidebar that holds every panel, and the status header over the polar view.
#include <cstdio>
#include <cstring>

#include <imgui.h>

#include "ui/panels/panels.h"

namespace ydscope::ui {
namespace {

}  // namespace

void draw_stats_panel(const UiModel& m) {
  if (!ImGui::CollapsingHeader("Statistics", ImGuiTreeNodeFlags_DefaultOpen)) return;
  const CounterSnapshot& c = m.snap.counters;
  if (!ImGui::BeginTable("stats", 4, ImGuiTableFlags_SizingStretchProp)) return;
  // Two name/value pairs per row keeps the panel short.
  auto pair = [](const char* name, const char* format, double value, bool warn) {
    ImGui::TableNextColumn();
    ImGui::TextDisabled("%s", name);
    ImGui::TableNextColumn();
    char text[48];
    std::snprintf(text, sizeof text, format, value);
    if (warn) ImGui::TextColored({1.0f, 0.6f, 0.35f, 1.0f}, "%s", text);
    else ImGui::TextUnformatted(text);
  };
  pair("bytes/s", "%.0f", c.bytes_per_s, false);
  pair("packets/s", "%.0f", c.packets_per_s, false);
  pair("laps/s", "%.2f", c.laps_per_s, false);
  pair("points/lap", "%.0f", static_cast<double>(m.points_in_lap), false);
  pair("checksum err", "%.0f", static_cast<double>(c.checksum_errors), c.checksum_errors > 0);
  pair("resync bytes", "%.0f", static_cast<double>(c.resync_bytes), c.resync_bytes > 0);
  pair("CRC8 fails", "%.0f", static_cast<double>(c.crc8_failures), c.crc8_failures > 0);
  pair("queue drops", "%.0f", static_cast<double>(m.snap.queue_dropped), m.snap.queue_dropped > 0);
  pair("laps skipped", "%.0f", static_cast<double>(m.laps_skipped), false);
  pair("reconnects", "%.0f", static_cast<double>(c.reconnects), c.reconnects > 0);
  pair("latency ms", "%.1f", m.latency_ms.mean(), false);
  pair("frame ms", "%.2f", m.frame_ms.mean(), false);
  pair("points drawn", "%.0f", static_cast<double>(m.points_drawn_total), false);
  pair("laps shown", "%.0f", static_cast<double>(m.laps_shown), false);
  ImGui::EndTable();
}

float draw_sidebar(UiModel& m, ViewSettings& v, Session& session) {
  const ImGuiViewport* viewport = ImGui::GetMainViewport();
  // Docked to the left edge at full height; the width is the user's (remembered in imgui.ini).
  ImGui::SetNextWindowPos(viewport->WorkPos, ImGuiCond_Always);
  ImGui::SetNextWindowSize({430.0f, viewport->WorkSize.y}, ImGuiCond_FirstUseEver);
  ImGui::SetNextWindowSizeConstraints({300.0f, viewport->WorkSize.y}, {viewport->WorkSize.x * 0.6f, viewport->WorkSize.y});
  const ImGuiWindowFlags flags = ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoTitleBar | ImGuiWindowFlags_NoCollapse |
                                 ImGuiWindowFlags_NoBringToFrontOnFocus;
  float width = 0.0f;
  if (ImGui::Begin("ydscope", nullptr, flags)) {
    ImGui::TextColored({0.45f, 0.75f, 1.0f, 1.0f}, "ydscope");
    ImGui::SameLine();
    ImGui::TextDisabled("Tab: panels   F11: full-screen");
    ImGui::Separator();
    draw_connection_panel(m, session);
    draw_device_panel(m, session);
    draw_health_panel(m, session);
    draw_frequency_panels(m, session);
    draw_view_panel(m, v);
    draw_filter_panel(m, v);
    draw_stats_panel(m);
  }
  width = ImGui::GetWindowWidth();
  ImGui::End();
  return width;
}

void draw_view_header(const UiModel& m, float view_left, float view_width) {
  // Along the bottom of the view, clear of the spoke labels at the edges: state line on the left,
  // the banner (why this source) centred above it.
  ImDrawList* draw = ImGui::GetForegroundDrawList();
  const float pad = 72.0f;  // above the spoke labels that sit in the bottom corners
  const float line = ImGui::GetTextLineHeightWithSpacing();
  const float bottom = ImGui::GetMainViewport()->WorkSize.y;
  const SessionSnapshot& s = m.snap;
  char text[256];
  const char* model = s.device && s.device->profile ? s.device->profile->name.data() : "";
  const auto measured = m.scan_rate.hz();
  int n = std::snprintf(text, sizeof text, "%s%s%s", model, *model ? "  \xE2\x80\xA2  " : "",
                        std::string(link_state_name(s.state)).c_str());
  if (measured && n > 0 && s.state == LinkState::Scanning) std::snprintf(text + n, sizeof text - static_cast<std::size_t>(n), "  \xE2\x80\xA2  %.1f Hz  \xE2\x80\xA2  %zu points", *measured, m.points_in_lap);
  const ImU32 state_colour = s.state == LinkState::Scanning ? IM_COL32(110, 230, 150, 255)
                             : (s.state == LinkState::Failed ? IM_COL32(255, 110, 100, 255) : IM_COL32(255, 200, 90, 255));
  float y = bottom - pad;
  draw->AddText({view_left + 16.0f, y}, state_colour, text);
  if (s.state != LinkState::Scanning && !s.message.empty()) {
    y -= line;
    draw->AddText({view_left + 16.0f, y}, IM_COL32(255, 200, 120, 255), s.message.c_str());
  }
  if (m.paused_view) {
    y -= line;
    draw->AddText({view_left + 16.0f, y}, IM_COL32(255, 255, 255, 220), "frozen (P to resume)");
  }
  if (!m.banner.empty()) {
    const ImVec2 size = ImGui::CalcTextSize(m.banner.c_str());
    const float x = view_left + (view_width - size.x) * 0.5f;
    const float by = 44.0f;
    draw->AddRectFilled({x - 14.0f, by - 6.0f}, {x + size.x + 14.0f, by + size.y + 6.0f}, IM_COL32(22, 45, 80, 215), 8.0f);
    draw->AddText({x, by}, IM_COL32(210, 230, 255, 255), m.banner.c_str());
  }
}

}  // namespace ydscope::ui
