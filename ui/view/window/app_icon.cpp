#include "ui/view/window/app_icon.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>

namespace ydscope::ui {

namespace {

// Everything below is in the SVG's 256-unit square, y down.
constexpr float kUnits = 256.0f;
constexpr float kCentre = 128.0f;

struct Rgba {
  float r, g, b, a;
};

// Paints `top` over `under` (straight alpha).
Rgba over(Rgba under, Rgba top) {
  const float a = top.a + under.a * (1.0f - top.a);
  if (a <= 0.0f) return {0, 0, 0, 0};
  const auto mix = [&](float t, float u) { return (t * top.a + u * under.a * (1.0f - top.a)) / a; };
  return {mix(top.r, under.r), mix(top.g, under.g), mix(top.b, under.b), a};
}

Rgba hex(std::uint32_t rgb, float alpha) {
  return {static_cast<float>((rgb >> 16) & 0xFF) / 255.0f, static_cast<float>((rgb >> 8) & 0xFF) / 255.0f,
          static_cast<float>(rgb & 0xFF) / 255.0f, alpha};
}

bool in_rounded_square(float x, float y) {
  constexpr float lo = 8.0f, hi = 248.0f, radius = 44.0f;
  const float cx = std::clamp(x, lo + radius, hi - radius);
  const float cy = std::clamp(y, lo + radius, hi - radius);
  return x >= lo && x <= hi && y >= lo && y <= hi && std::hypot(x - cx, y - cy) <= radius;
}

bool on_grid(float x, float y) {
  constexpr float half_width = 1.5f;
  const float r = std::hypot(x - kCentre, y - kCentre);
  for (const float ring : {36.0f, 70.0f, 104.0f})
    if (std::fabs(r - ring) <= half_width) return true;
  const bool along = y >= 24.0f && y <= 232.0f && std::fabs(x - kCentre) <= half_width;
  const bool across = x >= 24.0f && x <= 232.0f && std::fabs(y - kCentre) <= half_width;
  return along || across;
}

// The sweep: a band of scan from 40 to 210 degrees (counter-clockwise from the right, over the
// top), coloured blue to green to yellow from bottom left to top right like the SVG's gradient.
bool on_sweep(float x, float y, Rgba& colour) {
  const float dx = x - kCentre, dy = kCentre - y;
  const float r = std::hypot(dx, dy);
  float angle = std::atan2(dy, dx) * 180.0f / std::numbers::pi_v<float>;
  if (angle < 0.0f) angle += 360.0f;
  if (r < 62.0f || r > 88.0f || angle < 40.0f || angle > 210.0f) return false;
  const float t = std::clamp(((x - 8.0f) + (248.0f - y)) / 480.0f, 0.0f, 1.0f);
  const Rgba blue = hex(0x2f7cf6, 1), green = hex(0x3ef0a0, 1), yellow = hex(0xf7c932, 1);
  const auto lerp = [](Rgba a, Rgba b, float u) {
    return Rgba{a.r + (b.r - a.r) * u, a.g + (b.g - a.g) * u, a.b + (b.b - a.b) * u, 0.9f};
  };
  colour = t < 0.5f ? lerp(blue, green, t * 2.0f) : lerp(green, yellow, t * 2.0f - 1.0f);
  return true;
}

bool on_lidar(float x, float y) {
  if (std::hypot(x - kCentre, y - kCentre) <= 9.0f) return true;
  // The heading chevron: apex (128, 86), base from (117, 106) to (139, 106).
  if (y < 86.0f || y > 106.0f) return false;
  const float half = (y - 86.0f) / 20.0f * 11.0f;
  return std::fabs(x - kCentre) <= half;
}

Rgba paint(float x, float y) {
  if (!in_rounded_square(x, y)) return {0, 0, 0, 0};
  Rgba c = hex(0x0b0f17, 1);
  if (on_grid(x, y)) c = over(c, hex(0x8fa6cc, 0.35f));
  Rgba sweep{};
  if (on_sweep(x, y, sweep)) c = over(c, sweep);
  if (on_lidar(x, y)) c = hex(0xffffff, 1);
  return c;
}

}  // namespace

std::vector<std::uint8_t> app_icon_rgba(int size) {
  std::vector<std::uint8_t> pixels(static_cast<std::size_t>(std::max(size, 0)) * std::max(size, 0) * 4);
  if (size <= 0) return pixels;
  constexpr int kSamples = 4;  // per axis: smooth edges at small sizes
  const float unit = kUnits / static_cast<float>(size);
  for (int py = 0; py < size; ++py) {
    for (int px = 0; px < size; ++px) {
      std::array<float, 4> sum{};
      for (int sy = 0; sy < kSamples; ++sy) {
        for (int sx = 0; sx < kSamples; ++sx) {
          const Rgba c = paint((static_cast<float>(px) + (static_cast<float>(sx) + 0.5f) / kSamples) * unit,
                               (static_cast<float>(py) + (static_cast<float>(sy) + 0.5f) / kSamples) * unit);
          sum[0] += c.r * c.a;  // premultiplied while averaging
          sum[1] += c.g * c.a;
          sum[2] += c.b * c.a;
          sum[3] += c.a;
        }
      }
      const float n = kSamples * kSamples;
      const float a = sum[3] / n;
      std::uint8_t* out = &pixels[(static_cast<std::size_t>(py) * size + px) * 4];
      for (int k = 0; k < 3; ++k)
        out[k] =
            static_cast<std::uint8_t>(std::lround(a > 0 ? std::clamp(sum[k] / sum[3], 0.0f, 1.0f) * 255.0f : 0.0f));
      out[3] = static_cast<std::uint8_t>(std::lround(a * 255.0f));
    }
  }
  return pixels;
}

}  // namespace ydscope::ui
