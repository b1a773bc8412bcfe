#include "ui/view/status/hover_gate.h"

namespace ydscope::ui {

void HoverGate::update(bool in_window, bool moved, double now_s) {
  if (!in_window) ever_moved_ = false;  // coming back takes a move of its own
  if (moved && in_window) {
    ever_moved_ = true;
    last_move_s_ = now_s;
  }
  visible_ = enabled_ && in_window && ever_moved_ && now_s - last_move_s_ < kIdleSeconds;
}

}  // namespace ydscope::ui
