#pragma once
// In the booth view (full screen at a trade show) what is there for an operator gets out of the
// visitors' way: a banner ("No lidar found, showing the virtual G6") says its piece and fades, the
// pointer hides once nobody moves it, and persistence is long enough for trails to read as motion.
// The windowed view keeps all of them as they are.
#include "ui/view/status/view_state.h"

namespace ydscope::ui {

// A banner is shown whole this long, then fades out over kBannerFadeSeconds.
inline constexpr double kBannerHoldSeconds = 6.0;
inline constexpr double kBannerFadeSeconds = 2.0;
// The pointer hides after resting this long.
inline constexpr double kCursorRestSeconds = 3.0;
// The booth view's persistence, in laps.
inline constexpr int kBoothMinPersistence = 30;
inline constexpr int kBoothMaxPersistence = 60;

// 1 for a banner `age_s` old in the windowed view; in the booth view 1, then down to 0.
float banner_opacity(double age_s, bool booth);
// Whether the banner is part way through its fade, when the view must draw at the display's
// rate for it to fade smoothly even with no laps arriving.
bool banner_fading(double age_s, bool booth);
// Whether the pointer, last moved `rested_s` ago, is hidden.
bool cursor_hidden(double rested_s, bool booth);
// The persistence the booth view uses, given the windowed view's.
int booth_persistence(int windowed_laps);
// What the dimmed view says, for who is looking: the session's own sentence (advice such as which
// command lists the serial ports) is for an operator, so the booth view keeps the headline and the
// subtitle and leaves it out.
ViewState for_audience(ViewState state, bool booth);

}  // namespace ydscope::ui
