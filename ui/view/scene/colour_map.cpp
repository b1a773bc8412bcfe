#include "ui/view/scene/colour_map.h"

#include <algorithm>
#include <array>
#include <cmath>

namespace ydscope::ui {
namespace {

struct Stop {
  float r, g, b;
};

// Nine evenly spaced samples of each palette. Turbo starts at a mid blue rather than its near-black
// end so the nearest points stay visible on the dark background.
constexpr std::array<Stop, 9> kTurbo{{{0.27f, 0.36f, 0.86f},
                                      {0.16f, 0.56f, 0.99f},
                                      {0.10f, 0.79f, 0.86f},
                                      {0.20f, 0.94f, 0.60f},
                                      {0.55f, 0.99f, 0.27f},
                                      {0.86f, 0.89f, 0.22f},
                                      {0.99f, 0.66f, 0.18f},
                                      {0.93f, 0.37f, 0.07f},
                                      {0.76f, 0.16f, 0.02f}}};
// Viridis from a third of the way along: its purple start is nearly as dark as the background
// (contrast 1.3 : 1) and the nearest points vanished. From here on every colour stands out at least
// 3 : 1 (tests/ui/palette_contrast_test.cpp).
constexpr std::array<Stop, 9> kViridis{{{0.194f, 0.398f, 0.553f},
                                        {0.159f, 0.481f, 0.556f},
                                        {0.130f, 0.563f, 0.553f},
                                        {0.145f, 0.638f, 0.522f},
                                        {0.220f, 0.712f, 0.468f},
                                        {0.359f, 0.783f, 0.389f},
                                        {0.563f, 0.836f, 0.261f},
                                        {0.774f, 0.877f, 0.179f},
                                        {0.992f, 0.906f, 0.145f}}};

}  // namespace

std::uint8_t unit_to_byte(float v) {
  // Rounded by adding a half (the value is not negative): lround was a call a channel, and the
  // pixel merge makes four a sprite at every frame.
  return static_cast<std::uint8_t>(std::clamp(v, 0.0f, 1.0f) * 255.0f + 0.5f);
}

std::uint8_t scale_byte(std::uint8_t channel, float by) {
  return static_cast<std::uint8_t>(static_cast<float>(channel) * by + 0.5f);
}

std::string_view colour_mode_name(ColourMode mode) {
  switch (mode) {
    case ColourMode::Range: return "range";
    case ColourMode::Flag: return "interference flag";
    case ColourMode::LapAge: return "lap age";
    case ColourMode::Motion: return "motion";
    case ColourMode::Source: return "source";
  }
  return "?";
}

std::string_view palette_name(Palette palette) { return palette == Palette::Turbo ? "turbo" : "viridis"; }

Rgba8 sample_palette(Palette palette, float t) {
  const auto& stops = palette == Palette::Turbo ? kTurbo : kViridis;
  if (!(t >= 0.0f)) t = 0.0f;  // also catches NaN
  t = std::min(t, 1.0f);
  const float pos = t * static_cast<float>(stops.size() - 1);
  const std::size_t i = std::min(static_cast<std::size_t>(pos), stops.size() - 2);
  const float f = pos - static_cast<float>(i);
  const Stop& a = stops[i];
  const Stop& b = stops[i + 1];
  return {unit_to_byte(a.r + (b.r - a.r) * f), unit_to_byte(a.g + (b.g - a.g) * f), unit_to_byte(a.b + (b.b - a.b) * f),
          255};
}

Rgba8 flag_colour(PointFlag flag) {
  switch (flag) {
    case PointFlag::None: return {120, 220, 255, 255};
    case PointFlag::Reserved: return {170, 170, 170, 255};
    case PointFlag::Specular: return {255, 80, 200, 255};
    case PointFlag::AmbientLight: return {255, 190, 40, 255};
  }
  return {255, 255, 255, 255};
}

Rgba8 motion_colour(bool moving) { return moving ? Rgba8{255, 96, 48, 255} : Rgba8{88, 128, 170, 255}; }

Rgba8 lap_look(const ColourParams& params, float age) {
  age = std::clamp(age, 0.0f, 1.0f);
  Rgba8 c = params.mode == ColourMode::LapAge ? sample_palette(params.palette, 1.0f - age) : Rgba8{255, 255, 255, 255};
  // The newest lap is opaque; the oldest kept one is barely there.
  if (params.fade_old_laps) c.a = unit_to_byte(1.0f - 0.85f * age);
  return c;
}

Rgba8 point_colour(const ColourParams& params, const LapPoint& point, float age, bool moving) {
  const Rgba8 lap = lap_look(params, age);
  Rgba8 c;
  switch (params.mode) {
    case ColourMode::Range: {
      const float span = std::max(params.far_mm - params.near_mm, 1.0f);
      c = sample_palette(params.palette, (point.range_mm - params.near_mm) / span);
      break;
    }
    case ColourMode::Flag: c = flag_colour(point.flag); break;
    case ColourMode::LapAge: c = lap; break;
    // Older laps' hot points, fading, are the trails of whoever walked past.
    case ColourMode::Motion: c = motion_colour(moving); break;
    // A lone lidar has no other to tell apart from: white; several get their colours in source_cloud.
    case ColourMode::Source: c = {235, 235, 235, 255}; break;
  }
  c.a = lap.a;
  return c;
}

Rgba8 ghost_colour(PointFlag flag) {
  Rgba8 c = flag_colour(flag);
  c.a = 60;
  return c;
}

}  // namespace ydscope::ui
