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

// A pixel's four channels, worked on together (GCC's vector extension: SIMD on x86 and ARM alike).
using Channels = float __attribute__((vector_size(16)));

// A pixel's bytes as channels and back (values 0..255.5, cut towards zero). On x86 GCC makes of
// __builtin_convertvector to bytes one conversion a lane, through the integer registers; SSE2's
// packs do it in four instructions. Elsewhere (ARM's NEON narrows in a few) the vector extension.
#if defined(__SSE2__)
Channels load_pixel(const std::uint8_t* pixel) {
  std::int32_t bytes = 0;
  std::memcpy(&bytes, pixel, sizeof bytes);
  const __m128i zero = _mm_setzero_si128();
  const __m128i words = _mm_unpacklo_epi8(_mm_cvtsi32_si128(bytes), zero);
  return reinterpret_cast<Channels>(_mm_cvtepi32_ps(_mm_unpacklo_epi16(words, zero)));
}

void store_pixel(std::uint8_t* pixel, Channels channels) {
  const __m128i whole = _mm_cvttps_epi32(reinterpret_cast<__m128>(channels));
  const __m128i words = _mm_packs_epi32(whole, whole);
  const std::int32_t bytes = _mm_cvtsi128_si32(_mm_packus_epi16(words, words));
  std::memcpy(pixel, &bytes, sizeof bytes);
}
#else
using Bytes = std::uint8_t __attribute__((vector_size(4)));

Channels load_pixel(const std::uint8_t* pixel) {
  Bytes bytes;
  std::memcpy(&bytes, pixel, sizeof bytes);
  return __builtin_convertvector(bytes, Channels);
}

void store_pixel(std::uint8_t* pixel, Channels channels) {
  const Bytes bytes = __builtin_convertvector(channels, Bytes);
  std::memcpy(pixel, &bytes, sizeof bytes);
}
#endif

// Clamped to 0..1.
float unit_clamp(float v) { return std::min(std::max(v, 0.0f), 1.0f); }

// GLSL's smoothstep from 0 at `edge0` to 1 at `edge0 + 1 / inverse_width`.
float smoothstep(float edge0, float inverse_width, float x) {
  const float t = unit_clamp((x - edge0) * inverse_width);
  return t * t * (3.0f - 2.0f * t);
}

}  // namespace

// points.frag's coverage (1 inside, falling to 0 over a pixel at the rim) and brightened core, at
// the middle of each step of the squared distance from the centre (1 at the sprite's edge).
void SpriteSplat::tabulate_shading(float point_size_px) {
  const float rim = 2.0f / std::max(point_size_px, 1.0f), rim_from = 1.0f - rim, rim_inverse = 1.0f / rim;
  constexpr float kCoreInverse = 1.0f / 0.6f;
  shading_.resize(kShadingSteps);
  for (std::size_t i = 0; i < shading_.size(); ++i) {
    const float r = std::sqrt((static_cast<float>(i) + 0.5f) / static_cast<float>(kShadingSteps));
    shading_[i] = {1.0f - smoothstep(rim_from, rim_inverse, r), 0.35f * (1.0f - smoothstep(0.0f, kCoreInverse, r))};
  }
  shaded_for_px_ = point_size_px;
}

// A new size, or another ground: the whole picture is its ground again, and every tile changed.
void SpriteSplat::start_over(int width, int height, const SplatGround& ground) {
  frame_.width = width = std::max(width, 0);
  frame_.height = height = std::max(height, 0);
  if (ground.pixels.empty())
    pixels_.assign(static_cast<std::size_t>(width) * static_cast<std::size_t>(height) * 4, 0);
  else
    pixels_.assign(ground.pixels.begin(), ground.pixels.end());
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
  if (shaded_for_px_ != frame.point_size_px) tabulate_shading(frame.point_size_px);
  // normalised device coordinates -> pixels, as GL's viewport transform
  const float half_w = 0.5f * static_cast<float>(frame.width), half_h = 0.5f * static_cast<float>(frame.height);
  for (const PointVertex& p : points)
    splat(p, (p.x * frame.scale_x + frame.offset_x + 1.0f) * half_w,
          (p.y * frame.scale_y + frame.offset_y + 1.0f) * half_h);
  collect_runs(kDrawn, drawn_);
  collect_runs(kDrawn | kChanged, changed_);
}

// One sprite centred at (x, y) pixels: the pixels whose centres lie in its square, each shaded as
// points.frag shades it and blended over what the picture holds.
void SpriteSplat::splat(const PointVertex& point, float x, float y) {
  const float size = frame_.point_size_px, half = 0.5f * size;
  // Far outside (or not a number): nothing to draw, and no integer to make of it.
  if (!(x > -size && y > -size && x < static_cast<float>(frame_.width) + size &&
        y < static_cast<float>(frame_.height) + size))
    return;
  const int x0 = std::max(0, static_cast<int>(std::ceil(x - half - 0.5f)));
  const int x1 = std::min(frame_.width, static_cast<int>(std::ceil(x + half - 0.5f)));
  const int y0 = std::max(0, static_cast<int>(std::ceil(y - half - 0.5f)));
  const int y1 = std::min(frame_.height, static_cast<int>(std::ceil(y + half - 0.5f)));
  if (x0 >= x1 || y0 >= y1) return;
  // points.vert: the rim a stack of points would have built up
  const float alpha = static_cast<float>(point.colour.a) * kByte;
  const float blocked_at_half = 1.0f - (point.half_clear < 0.0f ? 1.0f - 0.5f * alpha : point.half_clear);
  const float rim_x = 4.0f * blocked_at_half - alpha, rim_y = 2.0f * alpha - 4.0f * blocked_at_half;
  // The colour with a fourth channel of 1, so the blend below gives the alpha channel too.
  const Channels colour{static_cast<float>(point.colour.r) * kByte, static_cast<float>(point.colour.g) * kByte,
                        static_cast<float>(point.colour.b) * kByte, 1.0f};
  const float to_unit = 2.0f / size;  // pixels to the sprite's radius
  const auto stride = static_cast<std::size_t>(frame_.width) * 4;
  // Held in locals: a store through a byte pointer may alias any member, which would be read
  // again after every pixel.
  const Shading* const shading_by_step = shading_.data();
  std::uint8_t* const picture = pixels_.data();
  for (int row = y0; row < y1; ++row) {
    const float dy = (static_cast<float>(row) + 0.5f - y) * to_unit;
    std::uint8_t* pixel = picture + static_cast<std::size_t>(row) * stride + static_cast<std::size_t>(x0) * 4;
    for (int column = x0; column < x1; ++column, pixel += 4) {
      const float dx = (static_cast<float>(column) + 0.5f - x) * to_unit;
      const float r_squared = dx * dx + dy * dy;
      if (r_squared >= 1.0f) continue;  // outside the circle: the shader's discard
      const Shading& shading = shading_by_step[static_cast<int>(r_squared * static_cast<float>(kShadingSteps))];
      const float coverage = shading.coverage;
      const float a = unit_clamp(coverage * (rim_x + rim_y * coverage));
      // Premultiplied "over": the shaded colour times its alpha, plus what was there times 1 - a.
      const Channels shaded = (colour + (1.0f - colour) * shading.brighten) * (a * 255.0f);
      store_pixel(pixel, shaded + load_pixel(pixel) * (1.0f - a) + 0.5f);  // rounded: 0.5 added, then cut
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
