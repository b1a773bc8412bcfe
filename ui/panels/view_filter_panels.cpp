// The view settings (colour, persistence, exports) and the interference filter.
#include <algorithm>
#include <cmath>
#include <cstdio>

#include <imgui.h>

#include "ui/panels/panels.h"

namespace ydscope::ui {
namespace {

// The booth view's (F11) title line and large figure, folded away: they matter at a stand only.
void draw_booth_choices(ViewSettings& v) {
  if (!ImGui::TreeNode("booth view")) return;
  char title[128];
  std::snprintf(title, sizeof title, "%s", v.booth_title.c_str());
  if (ImGui::InputText("title", title, sizeof title)) v.booth_title = title;
  int figure = static_cast<int>(v.booth_figure);
  if (ImGui::Combo("figure", &figure, "none\0visitors now\0nearest visitor\0"))
    v.booth_figure = static_cast<BoothFigureKind>(figure);
  ImGui::TreePop();
}

}  // namespace

void draw_view_panel(UiModel& m, ViewSettings& v) {
  if (!ImGui::CollapsingHeader("View", ImGuiTreeNodeFlags_DefaultOpen)) return;
  int mode = static_cast<int>(v.colours.mode);
  ImGui::TextDisabled("colour by");
  ImGui::SameLine();
  ImGui::RadioButton("range", &mode, 0);
  ImGui::SameLine();
  ImGui::RadioButton("flag", &mode, 1);
  ImGui::SameLine();
  ImGui::RadioButton("lap age", &mode, 2);
  ImGui::SameLine();
  ImGui::RadioButton("motion", &mode, 3);
  help_marker(
      "Returns closer than the room learned over the last 5 s (people walking past) hot, with fading trails; "
      "the room calm. The booth view's default.");
  if (m.several_sources() || v.colours.mode == ColourMode::Source) {
    ImGui::SameLine();
    ImGui::RadioButton("source", &mode, 4);
  }
  v.colours.mode = static_cast<ColourMode>(mode);
  if (v.colours.mode != ColourMode::Flag && v.colours.mode != ColourMode::Motion) {
    int palette = static_cast<int>(v.colours.palette);
    ImGui::TextDisabled("palette  ");
    ImGui::SameLine();
    ImGui::RadioButton("turbo", &palette, 0);
    ImGui::SameLine();
    ImGui::RadioButton("viridis", &palette, 1);
    v.colours.palette = static_cast<Palette>(palette);
  }
  if (v.colours.mode == ColourMode::Range && v.auto_range) {
    ImGui::TextDisabled("range colours follow the auto-range");
  } else if (v.colours.mode == ColourMode::Range) {
    float metres[2] = {v.colours.near_mm / 1000.0f, v.colours.far_mm / 1000.0f};
    if (ImGui::DragFloat2("near / far m", metres, 0.05f, 0.0f, 100.0f, "%.2f")) {
      v.colours.near_mm = std::max(metres[0], 0.0f) * 1000.0f;
      v.colours.far_mm = std::max(metres[1] * 1000.0f, v.colours.near_mm + 10.0f);
    }
  }
  ImGui::SliderFloat("point size", &v.point_size_px, 1.0f, 10.0f, "%.1f px");
  ImGui::SliderInt("persistence", &v.persistence_laps, 1, 60, "%d laps");
  ImGui::Checkbox("fade old laps", &v.colours.fade_old_laps);
  ImGui::SameLine();
  ImGui::Checkbox("smooth", &v.smooth);
  if (ImGui::IsItemHovered()) ImGui::SetTooltip("Draw at the display's rate so old laps fade between laps");
  ImGui::Checkbox("grid", &v.show_grid);
  ImGui::SameLine();
  ImGui::Checkbox("auto-range", &v.auto_range);
  if (m.several_sources()) {
    ImGui::SameLine();
    ImGui::Checkbox("split", &v.split_view);
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("Up to four sources side by side, each around itself");
  }
  if (ImGui::Button("Reset view")) m.requests.push_back(ResetView{});
  ImGui::SameLine();
  if (ImGui::Button(m.paused_view ? "Resume" : "Freeze")) m.paused_view = !m.paused_view;
  ImGui::SameLine();
  if (ImGui::Button("Screenshot")) m.requests.push_back(SaveScreenshot{});
  // The export takes what is on screen: frozen laps while frozen.
  ImGui::TextDisabled("CSV");
  ImGui::SameLine();
  if (ImGui::Button("Newest lap")) m.requests.push_back(ExportLapCsv{false});
  ImGui::SameLine();
  char every[48];
  std::snprintf(every, sizeof every, "All %zu shown laps", m.laps_on_screen);
  if (ImGui::Button(every)) m.requests.push_back(ExportLapCsv{true});
  ImGui::TextDisabled("MCAP");
  ImGui::SameLine();
  if (ImGui::Button("Shown laps as /scan, /points")) m.requests.push_back(ExportLapMcap{});
  if (!m.status_message.empty()) wrapped_text(m.status_message.c_str());
  draw_booth_choices(v);
}

void draw_filter_panel(UiModel& m, ViewSettings& v) {
  if (!ImGui::CollapsingHeader("Interference filter", ImGuiTreeNodeFlags_DefaultOpen)) return;
  ImGui::Checkbox("drop specular (flag 2)", &v.interference.drop_specular);
  ImGui::SameLine();
  ImGui::TextDisabled("%d / lap", static_cast<int>(m.cloud.newest_specular_removed));
  ImGui::Checkbox("drop ambient light (flag 3)", &v.interference.drop_ambient);
  ImGui::SameLine();
  ImGui::TextDisabled("%d / lap", static_cast<int>(m.cloud.newest_ambient_removed));
  ImGui::Checkbox("show removed as ghosts", &v.interference.show_ghosts);
  help_marker(
      "G1 marks samples hit by a mirror-like reflection (2) or strong ambient light (3). G6 and TG never set these "
      "flags.");
}

}  // namespace ydscope::ui
