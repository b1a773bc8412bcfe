#pragma once
// A person's hands on the app under Xvfb, through Xlib: find its window, move the pointer, tap
// keys. Key events go straight to the window (XSendEvent), as quickly as a person never could:
// a burst of taps arrives between two frames. Xlib's headers stay in x11_input.cpp: their macros
// (None, Status, Bool) would leak into every test file that includes this one.
#include <X11/keysym.h>

#include <chrono>
#include <string>
#include <vector>

struct _XDisplay;

namespace ydscope::test {

// Xlib's KeySym, Window and Time (all XIDs or server times: unsigned long).
using KeySym = unsigned long;

class X11Hands {
 public:
  X11Hands();
  ~X11Hands();
  X11Hands(const X11Hands&) = delete;
  X11Hands& operator=(const X11Hands&) = delete;
  explicit operator bool() const { return display_ != nullptr; }

  // The top-level window titled `title`, waiting up to `timeout` for it to be mapped.
  bool find_window(const std::string& title, std::chrono::seconds timeout);

  // `count` press-release pairs of `keysym`, all sent at once. X timestamps 50 ms apart, so
  // GLFW takes none of them for auto-repeat or for an input method's duplicate.
  void tap(KeySym keysym, int count);

  // A key held down (a modifier for a drag) until key_up; sent like tap's.
  void key_down(KeySym keysym);
  void key_up(KeySym keysym);

  // The left button pressed or let go where the pointer is (window coordinates = screen ones
  // without a window manager).
  void left_button(bool down, int x, int y);

  // Screen coordinates (without a window manager the app's window sits at 0,0); works with no
  // window open too, to park the pointer before the app starts.
  void move_pointer(int x, int y);

  // What the screen shows, as a person sees it (not what the app holds in its back buffer): the
  // top-left `width` x `height` pixels, RGB, top row first; empty if the server would not say.
  std::vector<unsigned char> look_at_screen(int width, int height);

 private:
  unsigned long search(unsigned long parent, const std::string& title);
  void send_key(bool press, unsigned int keycode, unsigned long time);

  _XDisplay* display_;
  unsigned long window_ = 0;
  unsigned long next_time_ = 100000;
};

}  // namespace ydscope::test
