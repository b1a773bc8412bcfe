#include "ui/view/status/booth_calm.h"

#include <algorithm>

namespace ydscope::ui {

float banner_opacity(double age_s, bool booth) {
  if (!booth || age_s <= kBannerHoldSeconds) return 1.0f;
  const double left = 1.0 - (age_s - kBannerHoldSeconds) / kBannerFadeSeconds;
  return static_cast<float>(std::clamp(left, 0.0, 1.0));
}

bool banner_fading(double age_s, bool booth) {
  return booth && age_s > kBannerHoldSeconds && age_s < kBannerHoldSeconds + kBannerFadeSeconds;
}

bool cursor_hidden(double rested_s, bool booth) { return booth && rested_s >= kCursorRestSeconds; }

int booth_persistence(int windowed_laps) {
  return std::clamp(windowed_laps, kBoothMinPersistence, kBoothMaxPersistence);
}

ViewState for_audience(ViewState state, bool booth) {
  if (booth) state.detail.clear();
  return state;
}

}  // namespace ydscope::ui
