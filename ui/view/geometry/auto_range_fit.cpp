#include "ui/view/geometry/auto_range_fit.h"

#include <cmath>

namespace ydscope::ui {

std::optional<float> AutoRangeFit::update(bool enabled, float target_mm) {
  // Off -> on (the A key, the checkbox): the user's zoom is what the view shows now.
  if (enabled && !was_enabled_) fitted_ = false;
  was_enabled_ = enabled;
  if (!enabled || target_mm <= 0.0f) return std::nullopt;
  if (fitted_ && std::fabs(target_mm - fitted_mm_) <= kChangeShare * fitted_mm_) return std::nullopt;
  fitted_ = true;
  fitted_mm_ = target_mm;
  return target_mm;
}

}  // namespace ydscope::ui
