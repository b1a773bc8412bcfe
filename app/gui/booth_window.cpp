#include "app/gui/booth_window.h"

#include <GLFW/glfw3.h>

#include "ui/view/status/booth_calm.h"

namespace ydscope::gui {

void BoothWindow::toggle(ui::ViewSettings& settings, std::size_t sources) {
  if (!on_) {
    GLFWmonitor* monitor = glfwGetPrimaryMonitor();
    const GLFWvidmode* mode = monitor ? glfwGetVideoMode(monitor) : nullptr;
    if (!mode) return;
    glfwGetWindowPos(window_, &windowed_[0], &windowed_[1]);
    glfwGetWindowSize(window_, &windowed_[2], &windowed_[3]);
    glfwSetWindowMonitor(window_, monitor, 0, 0, mode->width, mode->height, mode->refreshRate);
    on_ = true;
    settings.show_panels = false;
    // The booth view shows who walks past: motion colours, back to the user's mode on leaving;
    // several lidars keep their own colours, or they could not be told apart.
    windowed_colour_mode_ = settings.colours.mode;
    if (sources < 2) settings.colours.mode = ui::ColourMode::Motion;
    windowed_persistence_ = settings.persistence_laps;  // long enough for trails to read as motion
    settings.persistence_laps = ui::booth_persistence(settings.persistence_laps);
    return;
  }
  glfwSetWindowMonitor(window_, nullptr, windowed_[0], windowed_[1], windowed_[2], windowed_[3], 0);
  on_ = false;
  settings.show_panels = true;
  if (windowed_colour_mode_ && settings.colours.mode == ui::ColourMode::Motion)
    settings.colours.mode = *windowed_colour_mode_;
  windowed_colour_mode_.reset();
  if (windowed_persistence_) settings.persistence_laps = *windowed_persistence_;
  windowed_persistence_.reset();
}

void BoothWindow::follow_pointer(double now_s, bool pointer_moved) {
  if (pointer_moved) pointer_moved_s_ = now_s;
  const bool hide = ui::cursor_hidden(now_s - pointer_moved_s_, on_);
  if (hide == cursor_hidden_) return;
  cursor_hidden_ = hide;
  glfwSetInputMode(window_, GLFW_CURSOR, hide ? GLFW_CURSOR_HIDDEN : GLFW_CURSOR_NORMAL);
}

}  // namespace ydscope::gui
