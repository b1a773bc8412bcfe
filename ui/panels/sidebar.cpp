// The sidebar that holds every panel, docked to the left edge at full height.
#include <cstdio>
#include <algorithm>
#include <cstring>

#include <imgui.h>

#include "ui/panels/panels.h"
#include "ui/view/window/window_fit.h"

namespace ydscope::ui {

float draw_sidebar(UiModel& m, PanelEdits& e, ViewSettings& v) {
  const ImGuiViewport* viewport = ImGui::GetMainViewport();
  const float scale = ImGui::GetFontSize() / 16.0f;  // the theme's font is 16 px at scale 1
  const float height = viewport->WorkSize.y;
  const float widest = sidebar_max_width(viewport->WorkSize.x);
  // Docked to the left edge at full height; the width is the user's (remembered in imgui.ini),
  // within what leaves the polar view most of the window (ui/view/window/window_fit.h).
  ImGui::SetNextWindowPos(viewport->WorkPos, ImGuiCond_Always);
  ImGui::SetNextWindowSize({sidebar_width(viewport->WorkSize.x, scale), height}, ImGuiCond_FirstUseEver);
  ImGui::SetNextWindowSizeConstraints({std::min(300.0f * scale, widest), height}, {widest, height});
  // No background of ImGui's: the app clears the sidebar's rectangle to it (theme.h, sidebar_background).
  const ImGuiWindowFlags flags = ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoTitleBar | ImGuiWindowFlags_NoCollapse |
                                 ImGuiWindowFlags_NoBringToFrontOnFocus | ImGuiWindowFlags_NoBackground;
  float width = 0.0f;
  if (ImGui::Begin("ydscope", nullptr, flags)) {
    // Every widget leaves room on its right for its label, so none is cut off at a narrow sidebar.
    ImGui::PushItemWidth(-ImGui::GetFontSize() * 8.5f);
    // Three tabs, so each one's panels fit an 800 px tall window without scrolling: the lidar and
    // its settings, how it is drawn, and the numbers.
    draw_source_selector(m);
    if (ImGui::BeginTabBar("sidebar")) {
      const int wanted = m.show_sidebar_tab;
      // The open tab is remembered (settings.ini), so the next run opens on it.
      const auto tab = [&m, &v](const char* name, SidebarTab which) {
        const bool open = ImGui::BeginTabItem(
            name, nullptr, m.show_sidebar_tab == static_cast<int>(which) ? ImGuiTabItemFlags_SetSelected : 0);
        if (open) v.sidebar_tab = which;
        return open;
      };
      if (tab("Lidar", SidebarTab::Lidar)) {
        draw_connection_panel(m, e);
        draw_device_panel(m, e);
        draw_check_panel(m);  // under what the unit says it is: the check judges that unit
        draw_health_panel(m);
        draw_frequency_panels(m, e);
        ImGui::EndTabItem();
      }
      if (tab("View", SidebarTab::View)) {
        draw_view_panel(m, v);
        draw_filter_panel(m, v);
        draw_sectors_panel(m, e);
        draw_zones_panel(m, v);
        ImGui::EndTabItem();
      }
      if (tab("Statistics", SidebarTab::Statistics)) {
        draw_stats_panel(m);
        draw_plots_panel(m, e);
        ImGui::EndTabItem();
      }
      if (tab("Sources", SidebarTab::Sources)) {
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
