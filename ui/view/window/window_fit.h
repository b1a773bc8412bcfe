#pragma once
// Where the first window goes and how wide the sidebar is, from the monitor's work area and its
// content scale: the window never spills off a small screen (a 1280x800 window on a 1024x600
// screen put the lidar at the right edge and the status line below the screen), and the view
// keeps most of the width whatever the screen.
namespace ydscope::ui {

struct ScreenRect {
  int x = 0, y = 0, width = 0, height = 0;
};

// The window the app would like at content scale 1.
inline constexpr int kPreferredWindowWidth = 1280;
inline constexpr int kPreferredWindowHeight = 800;
// What a window manager's title bar takes above the window (at scale 1).
inline constexpr int kTitleBarAllowance = 32;

// The preferred size times `content_scale`, shrunk to the work area, centred in it. A work area
// of zero size (no monitor known) gives the preferred size at the origin.
ScreenRect first_window_rect(ScreenRect work_area, float content_scale);
// True when the preferred size and a title bar do not fit the work area: the window is then also
// maximised, so a window manager fits it, title bar and all, into the work area.
bool window_was_shrunk(ScreenRect work_area, float content_scale);

// The sidebar's width for a window `window_width` wide: 430 px at scale 1, but never more than
// 40 % of the window, so the polar view keeps at least 60 %.
float sidebar_width(float window_width, float content_scale);
// The widest the user may drag it.
float sidebar_max_width(float window_width);

}  // namespace ydscope::ui
