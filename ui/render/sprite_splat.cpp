#include "ui/render/sprite_splat.h"

#include <algorithm>
#include <cmath>
#include <cstring>

#if defined(__SSE2__)
#include <emmintrin.h>
#endif

namespace ydscope::ui {
namespace {

constexpr float kByte = 1.0f / 255.0f;

// Four pixels of a row at once, a lane each (GCC's vector extension: SSE2 on x86, NEON on ARM): a
// 3 px sprite is three rows of three.
using Lanes = float __attribute__((vector_size(16)));
using Words = std::int32_t __attribute__((vector_size(16)));
using Bits = std::uint32_t __attribute__((vector_size(16)));

Lanes square_root(Lanes v) {
#if defined(__SSE2__)
  return reinterpret_cast<Lanes>(_mm_sqrt_ps(reinterpret_cast<__m128>(v)));
#else
  for (int lane = 0; lane < 4; ++lane) v[lane] = std::sqrt(v[lane]);
  return v;
#endif
}

// Clamped to 0..1. The vector extension's `v < 0 ? 0 : v` keeps a NaN, which SSE's min and max
// need not: four instructions a clamp instead of ten.
Lanes unit_clamp(Lanes v) {
#if defined(__SSE2__)
  const __m128 clamped = _mm_min_ps(_mm_max_ps(reinterpret_cast<__m128>(v), _mm_setzero_ps()), _mm_set1_ps(1.0f));
  return reinterpret_cast<Lanes>(clamped);
#else
  const Lanes zero{}, one = zero + 1.0f;
  v = v < zero ? zero : v;
  return v > one ? one : v;
#endif
}

// The smallest whole number not below `v`, for `v` well inside an int's range: a conversion cuts
// towards zero, which is the ceiling below zero and one short of it above unless `v` is whole.
// (std::ceil without SSE4.1 is a dozen instructions, four times a sprite.)
int ceiling(float v) {
  const int cut = static_cast<int>(v);
  return static_cast<float>(cut) < v ? cut + 1 : cut;
}

// GLSL's smoothstep from 0 at `edge0` to 1 at `edge0 + 1 / inverse_width`.
Lanes smoothstep(float edge0, float inverse_width, Lanes x) {
  const Lanes t = unit_clamp((x - edge0) * inverse_width);
  return t * t * (3.0f - 2.0f * t);
}

// Four pixels from `pixel` on, RGBA bytes: each lane's shaded colour (premultiplied, 0..255) laid
// over what its pixel holds, with the lane's alpha `a`, and rounded (0.5 added, then cut). A lane
// with nothing shaded and `a` 0 gives its pixel back as it was.
void blend_four(std::uint8_t* pixel, Lanes red, Lanes green, Lanes blue, Lanes a) {
  Bits held;
  std::memcpy(&held, pixel, sizeof held);
  const Lanes keep = 1.0f - a;
  const auto channel = [&](int shift, Lanes shaded) {
    const Lanes was = __builtin_convertvector(reinterpret_cast<Words>((held >> shift) & 0xFFu), Lanes);
    return reinterpret_cast<Bits>(__builtin_convertvector(shaded + was * keep + 0.5f, Words)) << shift;
  };
  const Bits laid = channel(0, red) | channel(8, green) | channel(16, blue) | channel(24, a * 255.0f);
  std::memcpy(pixel, &laid, sizeof laid);
}

}  // namespace

// A new size, or another ground: the whole picture is its ground again, and every tile changed.
void SpriteSplat::start_over(int width, int height, const SplatGround& ground) {
  width = std::max(width, 0);
  height = std::max(height, 0);
  if (ground.pixels.empty())
    pixels_.assign(static_cast<std::size_t>(width) * static_cast<std::size_t>(height) * 4, 0);
  else
    pixels_.assign(ground.pixels.begin(), ground.pixels.end());
  // A row's last pixels are blended four at a time like the rest, the lanes past them left as they
  // were: the last row's run on past the picture's end.
  pixels_.resize(pixels_.size() + kSlackBytes);
  tile_columns_ = (width + kTilePx - 1) / kTilePx;
  tile_rows_ = (height + kTilePx - 1) / kTilePx;
  tile_marks_.assign(static_cast<std::size_t>(tile_columns_) * static_cast<std::size_t>(tile_rows_), kChanged);
}

// The last paint's tiles back to the ground: they, and only they, change.
void SpriteSplat::restore_drawn(const SplatGround& ground) {
  const auto row_bytes = static_cast<std::size_t>(frame_.width) * 4;
  for (const PixelBox& run : drawn_)
    for (int y = run.y; y < run.y + run.height; ++y) {
      const std::size_t at = static_cast<std::size_t>(y) * row_bytes + static_cast<std::size_t>(run.x) * 4;
      const auto bytes = static_cast<std::size_t>(run.width) * 4;
      if (ground.pixels.empty())
        std::memset(&pixels_[at], 0, bytes);
      else
        std::memcpy(&pixels_[at], &ground.pixels[at], bytes);
    }
  for (std::uint8_t& marks : tile_marks_) marks = (marks & kDrawn) != 0 ? kChanged : 0;
}

void SpriteSplat::paint(std::span<const PointVertex> points, const SplatFrame& frame, const SplatGround& ground) {
  // A ground of another size than the frame's is none: it would be read past its end.
  const bool grounded =
      !ground.pixels.empty() && ground.pixels.size() == static_cast<std::size_t>(std::max(frame.width, 0)) *
                                                            static_cast<std::size_t>(std::max(frame.height, 0)) * 4;
  const SplatGround under = grounded ? ground : SplatGround{};
  const std::optional<std::uint64_t> ground_generation =
      grounded ? std::optional<std::uint64_t>(ground.generation) : std::nullopt;
  if (frame.width != frame_.width || frame.height != frame_.height || ground_generation != ground_generation_)
    start_over(frame.width, frame.height, under);
  else
    restore_drawn(under);
  frame_ = frame;
  ground_generation_ = ground_generation;
  drawn_.clear();
  changed_.clear();
  if (frame.width <= 0 || frame.height <= 0) return;
  // normalised device coordinates -> pixels, as GL's viewport transform
  const float half_w = 0.5f * static_cast<float>(frame.width), half_h = 0.5f * static_cast<float>(frame.height);
  for (const PointVertex& p : points)
    splat(p, (p.x * frame.scale_x + frame.offset_x + 1.0f) * half_w,
          (p.y * frame.scale_y + frame.offset_y + 1.0f) * half_h);
  collect_runs(kDrawn, drawn_);
  collect_runs(kDrawn | kChanged, changed_);
}

// One sprite centred at (x, y) pixels: the pixels whose centres lie in its square, each shaded as
// points.frag shades it and blended over what the picture holds, four of a row at a time.
void SpriteSplat::splat(const PointVertex& point, float x, float y) {
  const float size = frame_.point_size_px, half = 0.5f * size;
  // Far outside (or not a number): nothing to draw, and no integer to make of it.
  if (!(x > -size && y > -size && x < static_cast<float>(frame_.width) + size &&
        y < static_cast<float>(frame_.height) + size))
    return;
  const int x0 = std::max(0, ceiling(x - half - 0.5f)), x1 = std::min(frame_.width, ceiling(x + half - 0.5f));
  const int y0 = std::max(0, ceiling(y - half - 0.5f)), y1 = std::min(frame_.height, ceiling(y + half - 0.5f));
  if (x0 >= x1 || y0 >= y1) return;
  // points.frag: coverage falls from 1 to 0 over the outer two pixels, the core is brightened
  const float rim = 2.0f / std::max(size, 1.0f), rim_from = 1.0f - rim, rim_inverse = 1.0f / rim;
  constexpr float kCoreInverse = 1.0f / 0.6f;
  // points.vert: the rim a stack of points would have built up
  const float alpha = static_cast<float>(point.colour.a) * kByte;
  const float blocked_at_half = 1.0f - (point.half_clear < 0.0f ? 1.0f - 0.5f * alpha : point.half_clear);
  const float rim_x = 4.0f * blocked_at_half - alpha, rim_y = 2.0f * alpha - 4.0f * blocked_at_half;
  const float red = static_cast<float>(point.colour.r) * kByte, green = static_cast<float>(point.colour.g) * kByte,
              blue = static_cast<float>(point.colour.b) * kByte;
  const float to_unit = 2.0f / size;  // pixels to the sprite's radius
  const Lanes centres = Lanes{0.5f, 1.5f, 2.5f, 3.5f} - x;
  const Words lane = {0, 1, 2, 3};
  const auto stride = static_cast<std::size_t>(frame_.width) * 4;
  // Held in a local: a store through a byte pointer may alias any member, which would be read
  // again after every store.
  std::uint8_t* const picture = pixels_.data();
  for (int row = y0; row < y1; ++row) {
    const float dy = (static_cast<float>(row) + 0.5f - y) * to_unit;
    std::uint8_t* pixel = picture + static_cast<std::size_t>(row) * stride + static_cast<std::size_t>(x0) * 4;
    for (int column = x0; column < x1; column += 4, pixel += 16) {
      const Lanes dx = (static_cast<float>(column) + centres) * to_unit;
      const Lanes r_squared = dx * dx + dy * dy;
      // Past the sprite's square, or outside its circle (the shader's discard): nothing drawn.
      const Words drawn = (lane < x1 - column) & (r_squared < 1.0f);
      const Lanes r = square_root(r_squared);
      const Lanes coverage = 1.0f - smoothstep(rim_from, rim_inverse, r);
      const Lanes brighten = 0.35f * (1.0f - smoothstep(0.0f, kCoreInverse, r));
      const Lanes a = drawn ? unit_clamp(coverage * (rim_x + rim_y * coverage)) : Lanes{};
      // Premultiplied "over": the shaded colour times its alpha, plus what was there times 1 - a.
      const Lanes a_levels = a * 255.0f;
      blend_four(pixel, (red + (1.0f - red) * brighten) * a_levels, (green + (1.0f - green) * brighten) * a_levels,
                 (blue + (1.0f - blue) * brighten) * a_levels, a);
    }
  }
  for (int ty = y0 / kTilePx; ty <= (y1 - 1) / kTilePx; ++ty)
    for (int tx = x0 / kTilePx; tx <= (x1 - 1) / kTilePx; ++tx)
      tile_marks_[static_cast<std::size_t>(ty * tile_columns_ + tx)] |= kDrawn;
}

void SpriteSplat::collect_runs(std::uint8_t bits, std::vector<PixelBox>& runs) const {
  const auto marked = [&](int tx, int ty) {
    return (tile_marks_[static_cast<std::size_t>(ty * tile_columns_ + tx)] & bits) != 0;
  };
  for (int ty = 0; ty < tile_rows_; ++ty) {
    const int y = ty * kTilePx, height = std::min(kTilePx, frame_.height - y);
    for (int tx = 0; tx < tile_columns_;) {
      if (!marked(tx, ty)) {
        ++tx;
        continue;
      }
      const int first = tx;
      while (tx < tile_columns_ && marked(tx, ty)) ++tx;
      const int x = first * kTilePx;
      runs.push_back({x, y, std::min(tx * kTilePx, frame_.width) - x, height});
    }
  }
}

}  // namespace ydscope::ui
