// Scan and ranging frequency (device commands), and the view and interference-filter settings.
#include <algorithm>
#include <cmath>
#include <cstdio>

#include <imgui.h>

#include "ui/panels/panels.h"

namespace ydscope::ui {
namespace {}  // namespace

CommandCallback track_command(UiModel& m, CommandControl control) {
  const std::uint64_t ticket = m.feedback->issued(control);
  return [feedback = m.feedback, control, ticket](const CommandResult& r) {
    feedback->finished(control, ticket, r.ok, r.what + ": " + r.message);
  };
}

void command_feedback_line(UiModel& m, CommandControl control) {
  const auto shown = m.feedback->shown(control, m.now_s);
  if (!shown) return;
  if (shown->pending) {
    static const char* const kSpin[] = {"|", "/", "-", "\\"};
    ImGui::TextColored({0.4f, 0.7f, 1.0f, 1.0f}, "%s %s...", kSpin[static_cast<int>(m.now_s * 8.0) % 4],
                       m.snap.busy_what.empty() ? "working" : m.snap.busy_what.c_str());
    return;
  }
  ImGui::PushStyleColor(ImGuiCol_Text, shown->ok ? ImVec4{0.35f, 0.9f, 0.55f, 1.0f} : ImVec4{1.0f, 0.45f, 0.4f, 1.0f});
  wrapped_text(shown->text.c_str());
  ImGui::PopStyleColor();
}

void draw_frequency_panels(UiModel& m, PanelEdits& e) {
  const SessionSnapshot& s = m.snap;
  const ModelProfile* profile = s.device ? s.device->profile : nullptr;
  // A replay has no device behind it to command.
  const bool can_command = link_state_connected(s.state) && !s.busy && profile && !m.replay.available;

  if (ImGui::CollapsingHeader("Scan frequency", ImGuiTreeNodeFlags_DefaultOpen)) {
    const auto measured = m.scan_rate.hz();
    // Set and measured side by side on one row: the sidebar's Lidar tab must fit 800 px.
    // Greyed under "last seen ..." while laps do not arrive; the buttons below stay as they are.
    if (const StaleValues stale(m); ImGui::BeginTable("scanhz", 4, ImGuiTableFlags_SizingStretchProp)) {
      ImGui::TableNextRow();
      ImGui::TableNextColumn();
      ImGui::TextDisabled("set (A5 0D)");
      ImGui::TableNextColumn();
      if (s.scan_hz)
        ImGui::Text("%.2f Hz", *s.scan_hz);
      else
        ImGui::TextDisabled("-");
      ImGui::TableNextColumn();
      ImGui::TextDisabled("measured");
      ImGui::TableNextColumn();
      if (measured)
        ImGui::Text("%.2f Hz", *measured);
      else
        ImGui::TextDisabled("-");
      ImGui::EndTable();
    }
    if (!can_command) ImGui::BeginDisabled();
    const double base = s.scan_hz.value_or(static_cast<double>(e.scan_target_hz));
    for (const double step : {-1.0, -0.1, 0.1, 1.0}) {
      char label[16];
      std::snprintf(label, sizeof label, "%+.1f", step);
      if (ImGui::Button(label)) {
        double target = std::round((base + step) * 10.0) / 10.0;
        if (profile) target = std::clamp(target, profile->min_scan_hz, profile->max_scan_hz);
        e.scan_target_hz = static_cast<float>(target);
        m.requests.push_back(SetScanHz{target});
      }
      ImGui::SameLine();
    }
    ImGui::NewLine();
    ImGui::SetNextItemWidth(110.0f);
    ImGui::InputFloat("Hz##target", &e.scan_target_hz, 0.0f, 0.0f, "%.1f");
    ImGui::SameLine();
    if (ImGui::Button("Set target")) m.requests.push_back(SetScanHz{static_cast<double>(e.scan_target_hz)});
    if (!can_command) ImGui::EndDisabled();
    if (profile) {
      ImGui::SameLine();
      ImGui::TextDisabled("%s: %.0f-%.0f Hz", std::string(profile->name).c_str(), profile->min_scan_hz,
                          profile->max_scan_hz);
    }
    command_feedback_line(m, CommandControl::ScanFrequency);
  }

  if (ImGui::CollapsingHeader("Ranging frequency")) {
    if (s.ranging_khz)
      ImGui::Text("current: %u kHz", static_cast<unsigned>(*s.ranging_khz));
    else
      ImGui::TextDisabled("current: unknown");
    if (profile && profile->ranging_settable) {
      if (!can_command) ImGui::BeginDisabled();
      for (const std::uint16_t khz : profile->ranging_khz) {
        char label[24];
        std::snprintf(label, sizeof label, "%u kHz", static_cast<unsigned>(khz));
        if (ImGui::RadioButton(label, s.ranging_khz && *s.ranging_khz == khz)) m.requests.push_back(SetRangingKhz{khz});
        ImGui::SameLine();
      }
      ImGui::NewLine();
      if (!can_command) ImGui::EndDisabled();
      command_feedback_line(m, CommandControl::RangingFrequency);
    } else if (profile) {
      ImGui::TextDisabled("%s reports its ranging frequency but cannot change it.", std::string(profile->name).c_str());
    }
  }
}

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
