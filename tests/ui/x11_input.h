#pragma once
// A person's hands on the app under Xvfb, through Xlib: find its window, move the pointer, tap
// keys. Key events go straight to the window (XSendEvent), as quickly as a person never could:
// a burst of taps arrives between two frames.
#include <X11/Xlib.h>
#include <X11/Xutil.h>
#include <X11/keysym.h>

#include <chrono>
#include <cstring>
#include <string>
#include <thread>

namespace ydscope::test {

class X11Hands {
 public:
  X11Hands() : display_(XOpenDisplay(nullptr)) {}
  ~X11Hands() {
    if (display_) XCloseDisplay(display_);
  }
  X11Hands(const X11Hands&) = delete;
  X11Hands& operator=(const X11Hands&) = delete;
  explicit operator bool() const { return display_ != nullptr; }

  // The top-level window titled `title`, waiting up to `timeout` for it to be mapped.
  bool find_window(const std::string& title, std::chrono::seconds timeout) {
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

  // `count` press-release pairs of `keysym`, all sent at once. X timestamps 50 ms apart, so
  // GLFW takes none of them for auto-repeat or for an input method's duplicate.
  void tap(KeySym keysym, int count) {
    const KeyCode code = XKeysymToKeycode(display_, keysym);
    for (int i = 0; i < count; ++i) {
      send(KeyPress, code, next_time_);
      send(KeyRelease, code, next_time_ + 10);
      next_time_ += 50;
    }
    XFlush(display_);
  }

  // A key held down (a modifier for a drag) until key_up; sent like tap's.
  void key_down(KeySym keysym) {
    send(KeyPress, XKeysymToKeycode(display_, keysym), next_time_);
    next_time_ += 50;
    XFlush(display_);
  }
  void key_up(KeySym keysym) {
    send(KeyRelease, XKeysymToKeycode(display_, keysym), next_time_);
    next_time_ += 50;
    XFlush(display_);
  }

  // The left button pressed or let go where the pointer is (window coordinates = screen ones
  // without a window manager).
  void left_button(bool down, int x, int y) {
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

  // Screen coordinates (without a window manager the app's window sits at 0,0); works with no
  // window open too, to park the pointer before the app starts.
  void move_pointer(int x, int y) {
    XWarpPointer(display_, None, DefaultRootWindow(display_), 0, 0, 0, 0, x, y);
    XFlush(display_);
  }

 private:
  Window search(Window parent, const std::string& title) {
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

  void send(int type, KeyCode code, Time time) {
    XKeyEvent event{};
    event.type = type;
    event.display = display_;
    event.window = window_;
    event.root = DefaultRootWindow(display_);
    event.subwindow = None;
    event.time = time;
    event.same_screen = True;
    event.keycode = code;
    event.state = 0;
    const long mask = type == KeyPress ? KeyPressMask : KeyReleaseMask;
    XSendEvent(display_, window_, True, mask, reinterpret_cast<XEvent*>(&event));
  }

  Display* display_;
  Window window_ = 0;
  Time next_time_ = 100000;
};

}  // namespace ydscope::test
