#include "app/gui/window_present.h"

#include <cstdlib>
#include <cstring>
#include <string_view>

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>
#define GLFW_EXPOSE_NATIVE_X11
#define GLFW_EXPOSE_NATIVE_GLX
#include <GLFW/glfw3native.h>
#include <X11/Xproto.h>

#include "ui/view/window/frame_pacing.h"

namespace ydscope::gui {
namespace {

// A box copied while the window was being resized can reach past the driver's back buffer, which
// the X server refuses (BadValue); Xlib's default answer to any error is to end the program. The
// next frame sees the new size and is drawn whole, so such a refusal is let go; any other error
// goes to the handler before this one.
XErrorHandler g_earlier_handler = nullptr;
int g_shm_opcode = -1;
constexpr int kShmPutImage = 3;  // MIT-SHM's minor opcode of ShmPutImage

int let_a_stale_copy_go(Display* display, XErrorEvent* error) {
  const bool copy =
      error->request_code == X_PutImage || (error->request_code == g_shm_opcode && error->minor_code == kShmPutImage);
  if (copy) return 0;
  return g_earlier_handler != nullptr ? g_earlier_handler(display, error) : 0;
}

// Copying part of the back buffer pays only where a frame costs its pixels: on a GPU a whole
// frame is cheap, and a driver's copy may wait for the display.
bool wants_sub_buffer_copies(const char* gl_renderer) {
  const char* asked = std::getenv("YDSCOPE_PRESENT");
  if (asked != nullptr && std::string_view(asked) == "swap") return false;
  return ui::is_software_renderer(gl_renderer);
}

}  // namespace

WindowPresenter::WindowPresenter(GLFWwindow* window, const char* gl_renderer) : window_(window) {
  if (!wants_sub_buffer_copies(gl_renderer)) return;
  Display* display = glfwGetX11Display();
  if (display == nullptr || glfwGetGLXWindow(window) == None) return;
  const char* extensions = glXQueryExtensionsString(display, DefaultScreen(display));
  if (extensions == nullptr || std::strstr(extensions, "GLX_MESA_copy_sub_buffer") == nullptr) return;
  copy_sub_buffer_ =
      reinterpret_cast<CopySubBuffer>(glXGetProcAddressARB(reinterpret_cast<const GLubyte*>("glXCopySubBufferMESA")));
  if (copy_sub_buffer_ == nullptr) return;
  int first_event = 0, first_error = 0;
  if (!XQueryExtension(display, "MIT-SHM", &g_shm_opcode, &first_event, &first_error)) g_shm_opcode = -1;
  g_earlier_handler = XSetErrorHandler(let_a_stale_copy_go);
}

void WindowPresenter::present(const ui::DrawnFrame& drawn) const {
  if (drawn.whole || copy_sub_buffer_ == nullptr) {
    glfwSwapBuffers(window_);
    return;
  }
  // Each copy is a request to the X server and a wait for it; a frame of points draws a few dozen
  // small boxes, which cost more copied one by one than copied in a few larger ones (the back
  // buffer is right everywhere, so a copy may take in pixels this frame did not draw).
  constexpr std::size_t kMaxCopies = 4;
  for (const ui::PixelBox& box : ui::joined_boxes(drawn.boxes, kMaxCopies))
    copy_sub_buffer_(glfwGetX11Display(), glfwGetGLXWindow(window_), box.x, box.y, box.width, box.height);
}

}  // namespace ydscope::gui
