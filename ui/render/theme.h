#pragma once
// The app's look: a dark, low-contrast frame around a bright scan, and fonts large enough to read
// across a booth. Fonts come from the system (DejaVu or Noto) with ImGui's own as the fallback.
#include <array>

struct ImFont;

namespace ydscope::ui {

struct Fonts {
  bool system_font = false;  // false: ImGui's built-in font, scaled
};

// Glyphs rasterised large (kDisplayFontPx x scale) for the overlay and the booth view, drawn at any
// smaller size without blur. Null before apply_theme; then ImGui's default font serves.
ImFont* display_font();
inline constexpr float kDisplayFontPx = 64.0f;

// Call after ImGui::CreateContext and before the first frame, and again (with the font atlas
// cleared) when the window's content scale changes. `scale` for HiDPI.
Fonts apply_theme(float scale);

// Background behind the polar view (also the GL clear colour).
inline constexpr float kBackground[4] = {0.035f, 0.043f, 0.060f, 1.0f};

// The sidebar's background: the theme's window colour as ImGui would blend it over kBackground.
// The app clears the sidebar's rectangle to it with GL instead of letting ImGui draw it: on a
// software renderer a blended 430 x 800 rectangle cost about 3 ms of CPU a frame, a cleared one
// next to nothing (docs/performance.md).
std::array<float, 4> sidebar_background();

}  // namespace ydscope::ui
