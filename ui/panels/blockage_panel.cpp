// Blockage in the Lidar tab: the Health section's header says which sectors stay empty while the
// rest of the turn sees returns, in the sentence the polar view's ring, /diagnostics and `check`
// use ("Health · blocked 40°–75° for 12 s", red). In the header, not a section of its own: the
// tab must still fit an 800 px window (tests/ui/sidebar_fit_test.cpp).
#include <string>

#include "ui/panels/panels.h"

namespace ydscope::ui {

bool draw_health_header(const UiModel& m) {
  const std::vector<BlockedSector> blocked = m.dropouts.blocked();
  if (blocked.empty()) return ImGui::CollapsingHeader("Health###health", ImGuiTreeNodeFlags_DefaultOpen);
  ImGui::PushStyleColor(ImGuiCol_Text, ImVec4{1.0f, 0.42f, 0.36f, 1.0f});
  const bool open = ImGui::CollapsingHeader(
      ("Health \xC2\xB7 " + describe_blocked_sectors(blocked) + "###health").c_str(), ImGuiTreeNodeFlags_DefaultOpen);
  ImGui::PopStyleColor();
  if (ImGui::IsItemHovered())
    ImGui::SetTooltip(
        "A sector is blocked when nearly every sample in it came back with no return over the last 3 s while the\n"
        "rest of the turn sees returns: a bracket, a cable or dirt on the window. The ring round the lidar on the\n"
        "view shows the share of no returns per degree, amber to red.");
  return open;
}

}  // namespace ydscope::ui
