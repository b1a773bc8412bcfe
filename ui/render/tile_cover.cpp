#include "ui/render/tile_cover.h"

#include <algorithm>
#include <cmath>

namespace ydscope::ui {

TileCover::TileCover(const DisplayBox& area, float tile_px) : area_(area), tile_px_(tile_px) {
  if (area.empty() || !(tile_px > 0.0f)) return;
  columns_ = static_cast<int>(std::ceil((area.x1 - area.x0) / tile_px));
  rows_ = static_cast<int>(std::ceil((area.y1 - area.y0) / tile_px));
  tiles_.assign(static_cast<std::size_t>(columns_ * rows_), 0);
}

void TileCover::mark(const DisplayBox& box) {
  const DisplayBox inside = box.intersected(area_);
  if (inside.empty()) return;
  // The ends are exclusive: a box ending on a tile's edge does not reach that tile.
  const auto first = [&](float at, float from) { return static_cast<int>(std::floor((at - from) / tile_px_)); };
  const auto last = [&](float at, float from) { return static_cast<int>(std::ceil((at - from) / tile_px_)) - 1; };
  const int c0 = std::max(first(inside.x0, area_.x0), 0), c1 = std::min(last(inside.x1, area_.x0), columns_ - 1);
  const int r0 = std::max(first(inside.y0, area_.y0), 0), r1 = std::min(last(inside.y1, area_.y0), rows_ - 1);
  for (int row = r0; row <= r1; ++row)
    std::fill_n(tiles_.begin() + row * columns_ + c0, std::max(c1 - c0 + 1, 0), std::uint8_t{1});
}

bool TileCover::unite(const TileCover& other) {
  if (!(other.area_ == area_) || other.tile_px_ != tile_px_) return false;
  for (std::size_t i = 0; i < tiles_.size(); ++i) tiles_[i] |= other.tiles_[i];
  return true;
}

TileCover TileCover::coarser() const {
  TileCover joined(area_, 2.0f * tile_px_);
  for (int row = 0; row < rows_; ++row)
    for (int column = 0; column < columns_; ++column)
      if (at(column, row)) joined.tiles_[static_cast<std::size_t>((row / 2) * joined.columns_ + column / 2)] = 1;
  return joined;
}

std::vector<DisplayBox> TileCover::boxes() const {
  // A run is [first, last] columns of marked tiles in a row; a box open in the row above with the
  // same run grows down into this row, any other run opens a box of its own.
  struct Open {
    int first, last, top;
    bool carried;
  };
  std::vector<Open> open, next;
  std::vector<DisplayBox> out;
  const auto close = [&](const Open& o, int bottom) {
    const DisplayBox box{
        area_.x0 + static_cast<float>(o.first) * tile_px_, area_.y0 + static_cast<float>(o.top) * tile_px_,
        area_.x0 + static_cast<float>(o.last + 1) * tile_px_, area_.y0 + static_cast<float>(bottom) * tile_px_};
    out.push_back(box.intersected(area_));
  };
  for (int row = 0; row <= rows_; ++row) {
    next.clear();
    for (int column = 0; row < rows_ && column < columns_;) {
      if (!at(column, row)) {
        ++column;
        continue;
      }
      const int first = column;
      while (column < columns_ && at(column, row)) ++column;
      const int last = column - 1;
      const auto same =
          std::find_if(open.begin(), open.end(), [&](Open& o) { return o.first == first && o.last == last; });
      if (same != open.end()) {
        same->carried = true;
        next.push_back({first, last, same->top, false});
      } else {
        next.push_back({first, last, row, false});
      }
    }
    for (const Open& o : open)
      if (!o.carried) close(o, row);
    open.swap(next);
  }
  return out;
}

std::size_t TileCover::marked() const {
  return static_cast<std::size_t>(std::count(tiles_.begin(), tiles_.end(), std::uint8_t{1}));
}

std::vector<DisplayBox> covering_boxes(const TileCover& cover, std::size_t max_boxes) {
  if (cover.marked() == 0) return {};
  TileCover tiles = cover;
  for (std::vector<DisplayBox> boxes = tiles.boxes();; boxes = tiles.boxes()) {
    if (boxes.size() <= std::max<std::size_t>(max_boxes, 1)) return boxes;
    const DisplayBox& area = tiles.area();
    // Tiles as large as the area are one box; coarser would not help.
    if (tiles.tile_px() >= std::max(area.x1 - area.x0, area.y1 - area.y0)) return {area};
    tiles = tiles.coarser();
  }
}

}  // namespace ydscope::ui
