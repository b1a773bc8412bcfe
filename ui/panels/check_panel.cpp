// Check, in the Lidar tab: "Run check" (on the Device panel's last line) runs the acceptance
// check `ydscope-cli check` runs on the selected lidar (docs/check.md); below the Device panel its
// progress shows, then the verdict in the CLI's words with each failed criterion and the report.
#include <imgui.h>

#include "ui/panels/panels.h"

namespace ydscope::ui {

void draw_run_check_button(UiModel& m) {
  const UnitCheckView& c = m.unit_check;
  const bool can_run = c.available && c.state != UnitCheckView::State::Running;
  if (!can_run) ImGui::BeginDisabled();
  if (ImGui::Button("Run check")) m.requests.emplace_back(RunCheck{});
  if (!can_run) ImGui::EndDisabled();
  if (ImGui::IsItemHovered(ImGuiHoveredFlags_AllowWhenDisabled))
    ImGui::SetTooltip(c.available ? "The acceptance check of ydscope-cli check, on this lidar: about 15 s,\n"
                                    "then the verdict here and the report in the browser"
                                  : "Run check needs a lidar (a port or the virtual lidar), not a recording");
}

void draw_check_panel(const UiModel& m) {
  // Nothing until there is something to say: the tab's other panels keep their room.
  const UnitCheckView& c = m.unit_check;
  if (c.state == UnitCheckView::State::Running) {
    ImGui::TextDisabled("checking ...");
    ImGui::TextWrapped("%s", c.progress.c_str());
    return;
  }
  if (c.state != UnitCheckView::State::Done) return;
  // The verdict as a badge in the report's colours: green PASS, red FAIL, grey INCOMPLETE.
  const ImVec4 colour = c.verdict == "PASS"   ? ImVec4(0.18f, 0.49f, 0.20f, 1.0f)
                        : c.verdict == "FAIL" ? ImVec4(0.78f, 0.16f, 0.16f, 1.0f)
                                              : ImVec4(0.42f, 0.45f, 0.50f, 1.0f);
  ImGui::PushStyleColor(ImGuiCol_Button, colour);
  ImGui::PushStyleColor(ImGuiCol_ButtonHovered, colour);
  ImGui::PushStyleColor(ImGuiCol_ButtonActive, colour);
  ImGui::Button(c.verdict.c_str());
  ImGui::PopStyleColor(3);
  ImGui::SameLine();
  ImGui::TextWrapped("%s", c.summary.c_str());
  for (const std::string& line : c.failures) ImGui::BulletText("%s", line.c_str());
  if (!c.report.empty()) ImGui::TextWrapped("report: %s", c.report.c_str());
  if (!c.report_note.empty()) ImGui::TextDisabled("%s", c.report_note.c_str());
}

}  // namespace ydscope::ui
