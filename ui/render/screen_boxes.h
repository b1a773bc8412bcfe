#pragma once
// Rectangles of the window in its two coordinate systems: ImGui's display coordinates (top-left
// origin, as a draw command's clip rectangle) and the framebuffer's pixels (bottom-left origin,
// as glScissor and glXCopySubBufferMESA take them).
#include <cstddef>
#include <vector>

namespace ydscope::ui {

// x0, y0, x1, y1 in display coordinates, the ends exclusive.
struct DisplayBox {
  float x0 = 0, y0 = 0, x1 = 0, y1 = 0;
  bool empty() const { return !(x1 > x0 && y1 > y0); }
  float area() const { return empty() ? 0.0f : (x1 - x0) * (y1 - y0); }
  DisplayBox united(const DisplayBox& other) const;
  DisplayBox intersected(const DisplayBox& other) const;
  bool overlaps(const DisplayBox& other) const { return !intersected(other).empty(); }
  friend bool operator==(const DisplayBox&, const DisplayBox&) = default;
};

struct PixelBox {
  int x = 0, y = 0, width = 0, height = 0;
  bool empty() const { return width <= 0 || height <= 0; }
  friend bool operator==(const PixelBox&, const PixelBox&) = default;
};

// What a frame drew: the whole window, or only these boxes of it (framebuffer pixels), or nothing.
struct DrawnFrame {
  bool whole = false;
  std::vector<PixelBox> boxes;
  bool drew() const { return whole || !boxes.empty(); }
};

// The same area or more in boxes none of which overlap another: overlapping ones become their union.
std::vector<DisplayBox> merged_boxes(std::vector<DisplayBox> boxes);

// At most `at_most` boxes holding all of `boxes`: the two whose union adds the fewest pixels are
// joined, again and again. For a copy of pixels that are right everywhere, where each copy costs
// more than the pixels it could leave out.
std::vector<PixelBox> joined_boxes(std::vector<PixelBox> boxes, std::size_t at_most);

// The framebuffer pixels `box` touches, at `scale` framebuffer pixels a display unit, in a
// framebuffer `framebuffer_height` pixels high.
PixelBox to_pixels(const DisplayBox& box, float scale, int framebuffer_height);

}  // namespace ydscope::ui
