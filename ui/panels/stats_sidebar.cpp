// Statistics, and the sidebar that holds every panel.
#include <cstdio>
#include <algorithm>
#include <cstring>

#include <imgui.h>

#include "ui/panels/panels.h"
#include "ui/view/window_fit.h"

namespace ydscope::ui {
void draw_stats_panel(const UiModel& m) {
  if (!ImGui::CollapsingHeader("Statistics", ImGuiTreeNodeFlags_DefaultOpen)) return;
  const CounterSnapshot& c = m.snap.counters;
  const StaleValues stale(m);
  if (!ImGui::BeginTable("stats", 4, ImGuiTableFlags_SizingStretchProp)) return;
  // Two name/value pairs per row keeps the panel short.
  auto pair = [&stale](const char* name, const char* format, double value, bool warn) {
    ImGui::TableNextColumn();
    ImGui::TextDisabled("%s", name);
    ImGui::TableNextColumn();
    char text[48];
    std::snprintf(text, sizeof text, format, value);
    if (warn)
      ImGui::TextColored(stale.colour({1.0f, 0.6f, 0.35f, 1.0f}), "%s", text);
    else
      ImGui::TextUnformatted(text);
  };
  pair("bytes/s", "%.0f", c.bytes_per_s, false);
  pair("packets/s", "%.0f", c.packets_per_s, false);
  pair("laps/s", "%.2f", c.laps_per_s, false);
  pair("points/lap", "%.0f", static_cast<double>(m.points_in_lap), false);
  pair("checksum err", "%.0f", static_cast<double>(c.checksum_errors), c.checksum_errors > 0);
  pair("resync bytes", "%.0f", static_cast<double>(c.resync_bytes), c.resync_bytes > 0);
  pair("CRC8 fails", "%.0f", static_cast<double>(c.crc8_failures), c.crc8_failures > 0);
  // Only a stream that lost its zero packets makes a lap longer than a lap can be.
  if (c.cut_points > 0) pair("points cut", "%.0f", static_cast<double>(c.cut_points), true);
  pair("queue drops", "%.0f", static_cast<double>(m.snap.queue_dropped), m.snap.queue_dropped > 0);
  pair("laps skipped", "%.0f", static_cast<double>(m.laps_skipped), false);
  pair("reconnects", "%.0f", static_cast<double>(c.reconnects), c.reconnects > 0);
  pair("latency ms", "%.1f", m.latency_ms.mean(), false);
  pair("frame ms", "%.2f", m.frame_ms.mean(), false);
  pair("frames/s", "%.1f", m.frame_interval_ms.mean() > 0.0 ? 1000.0 / m.frame_interval_ms.mean() : 0.0, false);
  pair("points drawn", "%.0f", static_cast<double>(m.points_drawn_total), false);
  pair("laps shown", "%.0f", static_cast<double>(m.laps_shown), false);
  ImGui::EndTable();
  // Every consumer of the lap stream has its own ring; one that falls behind drops only its own.
  if (m.snap.consumers.size() > 1) {
    ImGui::TextDisabled("lap consumers (ring, delivered, dropped)");
    for (const LapConsumerStats& consumer : m.snap.consumers) {
      const ImVec4 colour =
          consumer.dropped > 0 ? ImVec4{1.0f, 0.6f, 0.35f, 1.0f} : ImGui::GetStyleColorVec4(ImGuiCol_Text);
      ImGui::TextColored(colour, "  %s: %zu, %llu, %llu", consumer.name.c_str(), consumer.capacity,
                         static_cast<unsigned long long>(consumer.delivered),
                         static_cast<unsigned long long>(consumer.dropped));
    }
  }
}

float draw_sidebar(UiModel& m, PanelEdits& e, ViewSettings& v) {
  const ImGuiViewport* viewport = ImGui::GetMainViewport();
  const float scale = ImGui::GetFontSize() / 16.0f;  // the theme's font is 16 px at scale 1
  const float height = viewport->WorkSize.y;
  const float widest = sidebar_max_width(viewport->WorkSize.x);
  // Docked to the left edge at full height; the width is the user's (remembered in imgui.ini),
  // within what leaves the polar view most of the window (ui/view/window_fit.h).
  ImGui::SetNextWindowPos(viewport->WorkPos, ImGuiCond_Always);
  ImGui::SetNextWindowSize({sidebar_width(viewport->WorkSize.x, scale), height}, ImGuiCond_FirstUseEver);
  ImGui::SetNextWindowSizeConstraints({std::min(300.0f * scale, widest), height}, {widest, height});
  const ImGuiWindowFlags flags = ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoTitleBar | ImGuiWindowFlags_NoCollapse |
                                 ImGuiWindowFlags_NoBringToFrontOnFocus;
  float width = 0.0f;
  if (ImGui::Begin("ydscope", nullptr, flags)) {
    // Every widget leaves room on its right for its label, so none is cut off at a narrow sidebar.
    ImGui::PushItemWidth(-ImGui::GetFontSize() * 8.5f);
    // Three tabs, so each one's panels fit an 800 px tall window without scrolling: the lidar and
    // its settings, how it is drawn, and the numbers.
    draw_source_selector(m);
    if (ImGui::BeginTabBar("sidebar")) {
      const int wanted = m.show_sidebar_tab;
      const auto tab = [&m](const char* name, SidebarTab which) {
        return ImGui::BeginTabItem(name, nullptr,
                                   m.show_sidebar_tab == static_cast<int>(which) ? ImGuiTabItemFlags_SetSelected : 0);
      };
      if (tab("Lidar", SidebarTab::Lidar)) {
        draw_connection_panel(m, e);
        draw_device_panel(m, e);
        draw_health_panel(m);
        draw_frequency_panels(m, e);
        ImGui::EndTabItem();
      }
      if (tab("View", SidebarTab::View)) {
        draw_view_panel(m, v);
        draw_filter_panel(m, v);
        draw_sectors_panel(m, e);
        ImGui::EndTabItem();
      }
      if (tab("Statistics", SidebarTab::Statistics)) {
        draw_stats_panel(m);
        draw_plots_panel(m);
        ImGui::EndTabItem();
      }
      if (ImGui::BeginTabItem("Sources")) {
        draw_sources_panel(m, e);
        ImGui::EndTabItem();
      }
      if (wanted == m.show_sidebar_tab) m.show_sidebar_tab = -1;
      // The keys, one hover away instead of a row of their own.
      ImGui::TabItemButton("keys", ImGuiTabItemFlags_Trailing);
      if (ImGui::IsItemHovered())
        ImGui::SetTooltip(
            "Tab: hide the panels   F11: full-screen   R: reset view   A: auto-range\n"
            "P: freeze   S: screenshot   E: shown laps as CSV   M: as MCAP   W: share on/off\n"
            "N: next source   Esc: clear the ruler   Ctrl+Q: quit\n"
            "Wheel: zoom   drag: pan   double-click: reset   right-click twice: ruler\n"
            "Shift+drag: watch a sector   Alt+drag / Ctrl+drag: move / turn the selected source");
      ImGui::EndTabBar();
    }
    ImGui::PopItemWidth();
  }
  width = ImGui::GetWindowWidth();
  ImGui::End();
  return width;
}

}  // namespace ydscope::ui
