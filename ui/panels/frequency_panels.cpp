// Scan and ranging frequency: the device commands, with the outcome beside each control.
#include <algorithm>
#include <cmath>
#include <cstdio>

#include <imgui.h>

#include "ui/panels/panels.h"

namespace ydscope::ui {

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

}  // namespace ydscope::ui
