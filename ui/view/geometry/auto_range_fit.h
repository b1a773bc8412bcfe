#pragma once
// When auto-range refits the view. It follows the scan only on a real change (so the rings do not
// breathe with each lap's noise), and at once when the user turns it back on after zooming or
// panning by hand: the range it fitted last may be the same, but the view no longer shows it.
#include <optional>

namespace ydscope::ui {

class AutoRangeFit {
 public:
  // Refits smaller than this share of the fitted range are noise.
  static constexpr float kChangeShare = 0.15f;

  // Called each frame with the auto-range setting and the range the newest lap wants (<= 0: no
  // lap or no return). Returns the range to fit the view to now, if any.
  std::optional<float> update(bool enabled, float target_mm);
  // The view changed size or was reset: the next enabled frame refits.
  void forget() { fitted_ = false; }
  // The range fitted last (0 before the first fit), for the range colours.
  float fitted_mm() const { return fitted_mm_; }

 private:
  bool fitted_ = false;
  bool was_enabled_ = false;
  float fitted_mm_ = 0.0f;
};

}  // namespace ydscope::ui
