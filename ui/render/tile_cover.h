#pragma once
// The part of a view its points reach, as a few boxes. Between two laps a smooth view changes only
// where its points are (their fade moves); the background and grid elsewhere are what the last
// frame drew, and on a software renderer clearing and rastering them again was a good part of a
// frame. Each sprite marks the square tiles its box reaches; the marked tiles become boxes, each
// row's runs carried down the rows that repeat them. Where that gives more boxes than a frame
// should be drawn in, the tiles are made twice as large and the boxes counted again.
#include <cstddef>
#include <cstdint>
#include <vector>

#include "ui/render/screen_boxes.h"

namespace ydscope::ui {

class TileCover {
 public:
  TileCover() = default;  // covers nothing, over no area
  // Tiles `tile_px` square from the area's top-left corner; the last row and column may be cut.
  TileCover(const DisplayBox& area, float tile_px);

  // Marks every tile `box` reaches (the part of it inside the area).
  void mark(const DisplayBox& box);
  // Marks what `other` marks; false (and nothing marked) when it is over another area or tiling.
  bool unite(const TileCover& other);
  // The same area in tiles twice as large, marked where any of the four it joins is.
  TileCover coarser() const;
  // The marked tiles as boxes that do not overlap, in rows from the top, cut to the area.
  std::vector<DisplayBox> boxes() const;
  std::size_t marked() const;
  const DisplayBox& area() const { return area_; }
  float tile_px() const { return tile_px_; }

 private:
  bool at(int column, int row) const { return tiles_[static_cast<std::size_t>(row * columns_ + column)] != 0; }

  DisplayBox area_;
  float tile_px_ = 0.0f;
  int columns_ = 0, rows_ = 0;
  std::vector<std::uint8_t> tiles_;
};

// Boxes over every tile `cover` marks, at most `max_boxes` of them (the tiles made coarser until
// so; one box round the area at worst).
std::vector<DisplayBox> covering_boxes(const TileCover& cover, std::size_t max_boxes);

}  // namespace ydscope::ui
