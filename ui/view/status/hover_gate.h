#pragma once
// Whether the hover box (nearest point's angle and range) is shown. Only while a person is
// pointing: the pointer is in the window and moved lately. A pointer that never moved is not a
// person (Xvfb parks it at the screen's centre, over the view), and one that rests is not
// reading any more: the box would sit over the data, stale.
namespace ydscope::ui {

class HoverGate {
 public:
  // A resting pointer's box goes after this long.
  static constexpr double kIdleSeconds = 2.5;

  explicit HoverGate(bool enabled = true) : enabled_(enabled) {}
  // Each frame: is the pointer in the window, did it move since the last frame, and the time.
  void update(bool in_window, bool moved, double now_s);
  bool visible() const { return visible_; }

 private:
  bool enabled_;
  bool visible_ = false;
  bool ever_moved_ = false;
  double last_move_s_ = 0.0;
};

}  // namespace ydscope::ui
