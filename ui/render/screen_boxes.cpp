#include "ui/render/screen_boxes.h"

#include <algorithm>
#include <cmath>
#include <cstddef>

namespace ydscope::ui {

DisplayBox DisplayBox::united(const DisplayBox& other) const {
  if (empty()) return other;
  if (other.empty()) return *this;
  return {std::min(x0, other.x0), std::min(y0, other.y0), std::max(x1, other.x1), std::max(y1, other.y1)};
}

DisplayBox DisplayBox::intersected(const DisplayBox& other) const {
  return {std::max(x0, other.x0), std::max(y0, other.y0), std::min(x1, other.x1), std::min(y1, other.y1)};
}

std::vector<DisplayBox> merged_boxes(std::vector<DisplayBox> boxes) {
  std::erase_if(boxes, [](const DisplayBox& box) { return box.empty(); });
  for (bool merged = true; merged;) {
    merged = false;
    for (std::size_t i = 0; i < boxes.size() && !merged; ++i)
      for (std::size_t j = i + 1; j < boxes.size() && !merged; ++j)
        if (boxes[i].overlaps(boxes[j])) {
          boxes[i] = boxes[i].united(boxes[j]);
          boxes.erase(boxes.begin() + static_cast<std::ptrdiff_t>(j));
          merged = true;
        }
  }
  return boxes;
}

std::vector<PixelBox> joined_boxes(std::vector<PixelBox> boxes, std::size_t at_most) {
  std::erase_if(boxes, [](const PixelBox& box) { return box.empty(); });
  const auto area = [](const PixelBox& b) { return static_cast<long>(b.width) * b.height; };
  const auto united = [](const PixelBox& a, const PixelBox& b) {
    const int x0 = std::min(a.x, b.x), y0 = std::min(a.y, b.y);
    return PixelBox{x0, y0, std::max(a.x + a.width, b.x + b.width) - x0, std::max(a.y + a.height, b.y + b.height) - y0};
  };
  while (boxes.size() > std::max<std::size_t>(at_most, 1)) {
    std::size_t best_i = 0, best_j = 1;
    long best_growth = -1;
    for (std::size_t i = 0; i < boxes.size(); ++i)
      for (std::size_t j = i + 1; j < boxes.size(); ++j)
        if (const long growth = area(united(boxes[i], boxes[j])) - area(boxes[i]) - area(boxes[j]);
            best_growth < 0 || growth < best_growth) {
          best_growth = std::max(growth, 0L);
          best_i = i;
          best_j = j;
        }
    boxes[best_i] = united(boxes[best_i], boxes[best_j]);
    boxes.erase(boxes.begin() + static_cast<std::ptrdiff_t>(best_j));
  }
  return boxes;
}

PixelBox to_pixels(const DisplayBox& box, float scale, int framebuffer_height) {
  if (box.empty()) return {};
  const int left = static_cast<int>(std::floor(box.x0 * scale));
  const int right = static_cast<int>(std::ceil(box.x1 * scale));
  const int top = static_cast<int>(std::floor(box.y0 * scale));
  const int bottom = static_cast<int>(std::ceil(box.y1 * scale));
  return {left, framebuffer_height - bottom, right - left, bottom - top};
}

}  // namespace ydscope::ui
