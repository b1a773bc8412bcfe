// App, the keyboard shortcuts. Every press is queued by GLFW's key callback as it arrives and
// handled at the next frame: polling key state once per frame lost a quick tap whose press and
// release both fell between two frames (about 1 in 20 taps of P).
#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>
#include <imgui.h>

#include "app/gui/app.h"

namespace ydscope::gui {

void App::install_key_callback() {
  glfwSetWindowUserPointer(window_, this);
  // ImGui's backend installed its callback first; ours forwards to it, so text fields still type.
  imgui_key_callback_ =
      glfwSetKeyCallback(window_, [](GLFWwindow* window, int key, int scancode, int action, int mods) {
        auto* app = static_cast<App*>(glfwGetWindowUserPointer(window));
        if (app->imgui_key_callback_) app->imgui_key_callback_(window, key, scancode, action, mods);
        if (action == GLFW_PRESS) app->key_presses_.push_back({key, mods});
      });
  // Not the keys', but it needs the same pointer: an uncovered or resized window is drawn again
  // even when the frame would otherwise repeat the last one.
  glfwSetWindowRefreshCallback(
      window_, [](GLFWwindow* window) { static_cast<App*>(glfwGetWindowUserPointer(window))->window_damaged_ = true; });
}

void App::remove_key_callback() {
  glfwSetKeyCallback(window_, imgui_key_callback_);
  glfwSetWindowRefreshCallback(window_, nullptr);
  glfwSetWindowUserPointer(window_, nullptr);
}

void App::handle_keys() {
  std::vector<KeyPress> presses;
  presses.swap(key_presses_);
  // Typing in a text field is not a shortcut (ImGui's word from the frame that took the keys).
  if (ImGui::GetIO().WantTextInput) return;
  for (const KeyPress& press : presses) {
    const bool ctrl = (press.mods & GLFW_MOD_CONTROL) != 0;
    switch (press.key) {
      case GLFW_KEY_F11: booth_.toggle(settings_, sources_.size()); break;
      case GLFW_KEY_TAB: settings_.show_panels = !settings_.show_panels; break;
      case GLFW_KEY_R: model().requests.push_back(ui::ResetView{}); break;
      case GLFW_KEY_A: settings_.auto_range = true; break;
      case GLFW_KEY_P: model().paused_view = !model().paused_view; break;
      case GLFW_KEY_S: model().requests.push_back(ui::SaveScreenshot{}); break;
      case GLFW_KEY_E: model().requests.push_back(ui::ExportLapCsv{true}); break;
      case GLFW_KEY_M: model().requests.push_back(ui::ExportLapMcap{}); break;
      case GLFW_KEY_W: model().requests.push_back(ui::SetShare{!model().share.on}); break;
      case GLFW_KEY_ESCAPE: view_->clear_ruler(); break;
      // The next of several sources: the panels' and Alt/Ctrl+drag's, also with the panels hidden.
      case GLFW_KEY_N: model().requests.push_back(ui::SelectSource{(selected_ + 1) % sources_.size()}); break;
      case GLFW_KEY_Q:
        if (ctrl) quit_ = true;
        break;
      default: break;
    }
  }
}

}  // namespace ydscope::gui
