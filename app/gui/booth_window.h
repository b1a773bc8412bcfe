#pragma once
// The booth view's window: full screen on the primary monitor, with motion colours (unless
// several lidars need their own) and trails long enough to read as motion, and the pointer hidden
// once it rests. Leaving it puts the window back where it was and the user's settings back as
// they were.
#include <cstddef>
#include <optional>

#include "ui/view/settings/settings.h"

struct GLFWwindow;

namespace ydscope::gui {

class BoothWindow {
 public:
  explicit BoothWindow(GLFWwindow* window) : window_(window) {}

  bool on() const { return on_; }
  // Enters the booth view, or leaves it; `settings` changes as the booth needs. `sources`: how
  // many lidars the view shows. Nothing happens when there is no monitor to fill.
  void toggle(ui::ViewSettings& settings, std::size_t sources);
  // Each frame: a pointer that rests in the booth view is hidden; any move brings it back.
  void follow_pointer(double now_s, bool pointer_moved);

 private:
  GLFWwindow* window_;
  bool on_ = false;
  int windowed_[4] = {100, 100, 1280, 800};  // x, y, width, height to go back to
  std::optional<ui::ColourMode> windowed_colour_mode_;
  std::optional<int> windowed_persistence_;
  double pointer_moved_s_ = 0.0;
  bool cursor_hidden_ = false;
};

}  // namespace ydscope::gui
