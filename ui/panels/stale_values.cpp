// Numbers whose source went quiet stay in sight, greyed, under a line that says how old they are:
// an outage never leaves a green "normal" or a confident rate standing as if it were current.
#include <imgui.h>

#include "ui/panels/panels.h"

namespace ydscope::ui {

StaleValues::StaleValues(const UiModel& model) : age_s_(model.stale_for_s()) {
  if (!age_s_) return;
  const std::string note = "last seen " + format_age(*age_s_) + " ago";
  ImGui::TextColored({1.0f, 0.7f, 0.35f, 1.0f}, "%s", note.c_str());
  ImGui::PushStyleColor(ImGuiCol_Text, ImGui::GetStyleColorVec4(ImGuiCol_TextDisabled));
}

StaleValues::~StaleValues() {
  if (age_s_) ImGui::PopStyleColor();
}

ImVec4 StaleValues::colour(const ImVec4& live) const {
  return age_s_ ? ImGui::GetStyleColorVec4(ImGuiCol_TextDisabled) : live;
}

}  // namespace ydscope::ui
