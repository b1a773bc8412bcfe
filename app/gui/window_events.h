#pragma once
// What the window system says between two frames: each key press, in order, and whether the
// picture was lost (the window uncovered or resized). Every press is queued by GLFW's key callback
// as it arrives and taken at the next frame: polling key state once per frame lost a quick tap
// whose press and release both fell between two frames (about 1 in 20 taps of P).
#include <vector>

struct GLFWwindow;

namespace ydscope::gui {

struct KeyPress {
  int key;
  int mods;
};

class WindowEvents {
 public:
  // Installs its callbacks after ImGui's backend has installed its own; key events still reach
  // ImGui's first, so text fields type.
  explicit WindowEvents(GLFWwindow* window);
  ~WindowEvents();  // gives ImGui's key callback back
  WindowEvents(const WindowEvents&) = delete;
  WindowEvents& operator=(const WindowEvents&) = delete;

  // The presses since the last call, oldest first.
  std::vector<KeyPress> take_presses();
  // Whether the window must be drawn again since the last call (it starts so).
  bool take_damage();

 private:
  GLFWwindow* window_;
  void (*imgui_key_callback_)(GLFWwindow*, int, int, int, int) = nullptr;
  std::vector<KeyPress> presses_;
  bool damaged_ = true;
};

}  // namespace ydscope::gui
