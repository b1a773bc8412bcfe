// Small widgets every panel uses: a link state in its colour, wrapped text, a section rule, a (?) tip.
#include <string>

#include <imgui.h>

#include "ui/panels/panels.h"

namespace ydscope::ui {

void link_state_text(LinkState state, const char* message) {
  ImVec4 colour{0.7f, 0.7f, 0.7f, 1.0f};
  switch (state) {
    case LinkState::Scanning: colour = {0.35f, 0.90f, 0.55f, 1.0f}; break;
    case LinkState::Ready:
    case LinkState::Connecting:
    case LinkState::Probing:
    case LinkState::CommandInProgress: colour = {0.40f, 0.70f, 1.0f, 1.0f}; break;
    case LinkState::Stalled:
    case LinkState::Reconnecting: colour = {1.0f, 0.75f, 0.30f, 1.0f}; break;
    case LinkState::Failed: colour = {1.0f, 0.40f, 0.40f, 1.0f}; break;
    case LinkState::Idle: break;
  }
  ImGui::TextColored(colour, "%s", std::string(link_state_name(state)).c_str());
  if (message && *message) {
    ImGui::SameLine();
    ImGui::PushTextWrapPos(0.0f);
    ImGui::TextUnformatted(message);
    ImGui::PopTextWrapPos();
  }
}

void wrapped_text(const char* text) {
  ImGui::PushTextWrapPos(0.0f);
  ImGui::TextUnformatted(text);
  ImGui::PopTextWrapPos();
}

void section(const char* title) {
  ImGui::Spacing();
  ImGui::TextDisabled("%s", title);
  ImGui::Separator();
}

void help_marker(const char* text) {
  ImGui::SameLine();
  ImGui::TextDisabled("(?)");
  if (ImGui::IsItemHovered()) {
    ImGui::BeginTooltip();
    ImGui::PushTextWrapPos(ImGui::GetFontSize() * 30.0f);
    ImGui::TextUnformatted(text);
    ImGui::PopTextWrapPos();
    ImGui::EndTooltip();
  }
}

}  // namespace ydscope::ui
