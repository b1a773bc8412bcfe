#include "ui/x11_input.h"

#include <X11/Xlib.h>
#include <X11/Xutil.h>

#include <thread>

namespace ydscope::test {

X11Hands::X11Hands() : display_(XOpenDisplay(nullptr)) {}

X11Hands::~X11Hands() {
  if (display_) XCloseDisplay(display_);
}

bool X11Hands::find_window(const std::string& title, std::chrono::seconds timeout) {
  const auto deadline = std::chrono::steady_clock::now() + timeout;
  while (std::chrono::steady_clock::now() < deadline) {
    if ((window_ = search(DefaultRootWindow(display_), title)) != 0) {
      XWindowAttributes attributes{};
      if (XGetWindowAttributes(display_, window_, &attributes) && attributes.map_state == IsViewable) return true;
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(100));
  }
  return false;
}

void X11Hands::tap(KeySym keysym, int count) {
  const KeyCode code = XKeysymToKeycode(display_, keysym);
  for (int i = 0; i < count; ++i) {
    send_key(true, code, next_time_);
    send_key(false, code, next_time_ + 10);
    next_time_ += 50;
  }
  XFlush(display_);
}

void X11Hands::key_down(KeySym keysym) {
  send_key(true, XKeysymToKeycode(display_, keysym), next_time_);
  next_time_ += 50;
  XFlush(display_);
}

void X11Hands::key_up(KeySym keysym) {
  send_key(false, XKeysymToKeycode(display_, keysym), next_time_);
  next_time_ += 50;
  XFlush(display_);
}

void X11Hands::left_button(bool down, int x, int y) {
  XButtonEvent event{};
  event.type = down ? ButtonPress : ButtonRelease;
  event.display = display_;
  event.window = window_;
  event.root = DefaultRootWindow(display_);
  event.time = next_time_;
  event.x = event.x_root = x;
  event.y = event.y_root = y;
  event.button = Button1;
  event.same_screen = True;
  next_time_ += 50;
  XSendEvent(display_, window_, True, down ? ButtonPressMask : ButtonReleaseMask, reinterpret_cast<XEvent*>(&event));
  XFlush(display_);
}

void X11Hands::move_pointer(int x, int y) {
  XWarpPointer(display_, None, DefaultRootWindow(display_), 0, 0, 0, 0, x, y);
  XFlush(display_);
}

std::vector<unsigned char> X11Hands::look_at_screen(int width, int height) {
  XImage* image = XGetImage(display_, DefaultRootWindow(display_), 0, 0, static_cast<unsigned>(width),
                            static_cast<unsigned>(height), AllPlanes, ZPixmap);
  if (image == nullptr) return {};
  std::vector<unsigned char> rgb;
  rgb.reserve(static_cast<std::size_t>(width) * static_cast<std::size_t>(height) * 3);
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) {
      const unsigned long pixel = XGetPixel(image, x, y);
      rgb.push_back(static_cast<unsigned char>((pixel & image->red_mask) >> __builtin_ctzl(image->red_mask)));
      rgb.push_back(static_cast<unsigned char>((pixel & image->green_mask) >> __builtin_ctzl(image->green_mask)));
      rgb.push_back(static_cast<unsigned char>((pixel & image->blue_mask) >> __builtin_ctzl(image->blue_mask)));
    }
  XDestroyImage(image);
  return rgb;
}

unsigned long X11Hands::search(unsigned long parent, const std::string& title) {
  char* name = nullptr;
  if (XFetchName(display_, parent, &name) && name) {
    const bool match = title == name;
    XFree(name);
    if (match) return parent;
  }
  Window root = 0, up = 0, *children = nullptr;
  unsigned int n = 0;
  Window found = 0;
  if (XQueryTree(display_, parent, &root, &up, &children, &n)) {
    for (unsigned int i = 0; i < n && !found; ++i) found = search(children[i], title);
    if (children) XFree(children);
  }
  return found;
}

void X11Hands::send_key(bool press, unsigned int keycode, unsigned long time) {
  XKeyEvent event{};
  event.type = press ? KeyPress : KeyRelease;
  event.display = display_;
  event.window = window_;
  event.root = DefaultRootWindow(display_);
  event.subwindow = None;
  event.time = time;
  event.same_screen = True;
  event.keycode = keycode;
  event.state = 0;
  XSendEvent(display_, window_, True, press ? KeyPressMask : KeyReleaseMask, reinterpret_cast<XEvent*>(&event));
}

}  // namespace ydscope::test
