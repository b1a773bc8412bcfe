#include "app/gui/window_events.h"

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

namespace ydscope::gui {
namespace {

WindowEvents& events_of(GLFWwindow* window) { return *static_cast<WindowEvents*>(glfwGetWindowUserPointer(window)); }

}  // namespace

WindowEvents::WindowEvents(GLFWwindow* window) : window_(window) {
  glfwSetWindowUserPointer(window_, this);
  imgui_key_callback_ = glfwSetKeyCallback(window_, [](GLFWwindow* w, int key, int scancode, int action, int mods) {
    WindowEvents& events = events_of(w);
    if (events.imgui_key_callback_) events.imgui_key_callback_(w, key, scancode, action, mods);
    if (action == GLFW_PRESS) events.presses_.push_back({key, mods});
  });
  glfwSetWindowRefreshCallback(window_, [](GLFWwindow* w) { events_of(w).damaged_ = true; });
}

WindowEvents::~WindowEvents() {
  glfwSetKeyCallback(window_, imgui_key_callback_);
  glfwSetWindowRefreshCallback(window_, nullptr);
  glfwSetWindowUserPointer(window_, nullptr);
}

std::vector<KeyPress> WindowEvents::take_presses() {
  std::vector<KeyPress> presses;
  presses.swap(presses_);
  return presses;
}

bool WindowEvents::take_damage() {
  const bool damaged = damaged_;
  damaged_ = false;
  return damaged;
}

}  // namespace ydscope::gui
