#pragma once
// Puts a drawn frame on the screen. A swap shows the whole back buffer and leaves it undefined, so
// every frame must draw every pixel. On a software renderer (Mesa's llvmpipe: robots' boards, VMs,
// remote desktops, CI) that was most of the app's CPU, though a streaming frame changes the view
// and seldom the panels. Where Mesa offers GLX_MESA_copy_sub_buffer, the back buffer is never
// swapped: it keeps the last picture, a frame draws only the boxes that changed, and only those
// are copied to the window. Elsewhere (a GPU, or YDSCOPE_PRESENT=swap in the environment) frames
// are whole and swapped as before.
#include "ui/render/screen_boxes.h"

struct GLFWwindow;

namespace ydscope::gui {

class WindowPresenter {
 public:
  // `gl_renderer`: GL_RENDERER of the window's current context.
  WindowPresenter(GLFWwindow* window, const char* gl_renderer);

  // Whether a frame may draw only the boxes that changed: the back buffer keeps the rest.
  bool keeps_last_picture() const { return copy_sub_buffer_ != nullptr; }
  // Shows what the frame drew: a whole frame by a swap (the driver sizes it to the window as it
  // is now, even mid-resize), boxes by copying them.
  void present(const ui::DrawnFrame& drawn) const;

 private:
  using CopySubBuffer = void (*)(void* display, unsigned long drawable, int x, int y, int width, int height);
  GLFWwindow* window_;
  CopySubBuffer copy_sub_buffer_ = nullptr;
};

}  // namespace ydscope::gui
