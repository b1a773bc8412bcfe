#pragma once
// The app's icon as pixels, drawn from the same shapes as assets/ydscope.svg (rings, a sweep of
// scan, the lidar), so the window can carry it without an image loader or a second asset.
#include <cstdint>
#include <vector>

namespace ydscope::ui {

// size x size RGBA bytes, rows top to bottom; transparent outside the rounded square.
std::vector<std::uint8_t> app_icon_rgba(int size);

}  // namespace ydscope::ui
