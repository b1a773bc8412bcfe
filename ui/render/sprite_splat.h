#pragma once
// The view's point sprites drawn on the CPU, for a software renderer. llvmpipe spends about 430 ns
// of CPU on every point sprite it draws (binning, a fragment shader call for each 4 x 4 block it
// touches, the blend), whatever its size; with four lidars that was most of the app's CPU. Drawn
// here with the point shader's own formulas (shaders/points.vert, points.frag), four pixels of a
// row at a time, a 3-pixel sprite costs about 70 ns (bench_frame's BM_SpriteSplat).
//
// The picture has rows bottom-up like GL's. Over nothing it is premultiplied RGBA8: laid over what
// lies under with (ONE, ONE_MINUS_SRC_ALPHA), it gives what the sprites blended one by one would
// have. Over a ground it is that ground with the sprites blended over it, one by one.
#include <cstddef>
#include <cstdint>
#include <optional>
#include <span>
#include <vector>

#include "ui/render/screen_boxes.h"
#include "ui/view/scene/point_cloud.h"

namespace ydscope::ui {

// Where the sprites land: world millimetres to the picture's pixels (bottom-up), as GL's viewport
// maps normalised device coordinates, and the picture's size.
struct SplatFrame {
  float scale_x = 1.0f, scale_y = 1.0f;  // world mm -> normalised device coordinates
  float offset_x = 0.0f, offset_y = 0.0f;
  int width = 0, height = 0;  // pixels
  float point_size_px = 3.0f;
  friend bool operator==(const SplatFrame&, const SplatFrame&) = default;
};

// What the sprites are painted over: nothing (a picture premultiplied over nothing, blended over
// the view), or an opaque picture the size of the frame (the view's backdrop), which the painted
// picture then stands in for: laid without a blend, the backdrop and the sprites in one pass.
struct SplatGround {
  std::span<const std::uint8_t> pixels;  // RGBA, the frame's size, bottom row first; empty: nothing
  std::uint64_t generation = 0;          // changes whenever the pixels do
};

class SpriteSplat {
 public:
  // Square tiles in which the picture keeps track of what it drew: cleared, uploaded and laid by
  // the tile, so a wall's sprites cost a wall's worth of pixels, not the view's.
  static constexpr int kTilePx = 16;

  // Draws `points` (the first at the bottom) over `ground`, the last paint's sprites gone.
  void paint(std::span<const PointVertex> points, const SplatFrame& frame, const SplatGround& ground = {});

  // Premultiplied RGBA, `width` x `height`, bottom row first.
  const std::uint8_t* pixels() const { return pixels_.data(); }
  int width() const { return frame_.width; }
  int height() const { return frame_.height; }
  // The tiles the last paint drew in, as runs along each row of tiles, cut to the picture (pixels,
  // bottom-up); outside them the picture is its ground.
  const std::vector<PixelBox>& drawn() const { return drawn_; }
  // The tiles whose pixels the last paint may have changed from the paint before (the tiles either
  // drew in; the whole picture after a new size or ground), as runs like drawn()'s: what a copy of
  // the picture kept whole must take again.
  const std::vector<PixelBox>& changed() const { return changed_; }

 private:
  // Bytes past the picture's last pixel: a row's last pixels are blended four at a time.
  static constexpr std::size_t kSlackBytes = 12;
  void start_over(int width, int height, const SplatGround& ground);
  void restore_drawn(const SplatGround& ground);
  void splat(const PointVertex& point, float x, float y);
  // Runs along each row of tiles of those whose mark has any of `bits`.
  void collect_runs(std::uint8_t bits, std::vector<PixelBox>& runs) const;

  SplatFrame frame_;
  std::vector<std::uint8_t> pixels_;
  // Painted over nothing, or the generation of the ground painted over.
  std::optional<std::uint64_t> ground_generation_;
  int tile_columns_ = 0, tile_rows_ = 0;
  // Each tile's marks: kDrawn by this paint, kChanged since the last.
  static constexpr std::uint8_t kDrawn = 1, kChanged = 2;
  std::vector<std::uint8_t> tile_marks_;
  std::vector<PixelBox> drawn_, changed_;
};

}  // namespace ydscope::ui
