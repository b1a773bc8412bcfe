// A device command's outcome filed under the control that issued it, and the line that shows it.
#include <imgui.h>

#include "ui/panels/panels.h"

namespace ydscope::ui {

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

}  // namespace ydscope::ui
