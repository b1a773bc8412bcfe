#pragma once
// How a point gets its colour: by range (a perceptual palette), by G1 interference flag, or by the
// age of its lap; older laps of the persistence fade out.
#include <cstdint>
#include <string_view>

#include "core/protocol/lap.h"
#include "ui/view/geometry/geometry.h"

namespace ydscope::ui {

// Motion: returns closer than the learned room hot, the room calm (motion_background.h).
// Source: each lidar's own colour when several are shown (source_cloud.h).
enum class ColourMode : std::uint8_t { Range, Flag, LapAge, Motion, Source };
enum class Palette : std::uint8_t { Turbo, Viridis };

std::string_view colour_mode_name(ColourMode mode);
std::string_view palette_name(Palette palette);

// t in [0, 1] (clamped) -> colour along the palette, interpolated between its stops.
Rgba8 sample_palette(Palette palette, float t);

// A 0..1 channel as a byte, rounded, out-of-range values clamped.
std::uint8_t unit_to_byte(float v);

// A byte channel times `by` (0..1), rounded: a fade or a dimming.
std::uint8_t scale_byte(std::uint8_t channel, float by);

// Colours of the interference flags, also used by the legend in the panels.
Rgba8 flag_colour(PointFlag flag);

struct ColourParams {
  ColourMode mode = ColourMode::Range;
  Palette palette = Palette::Turbo;
  float near_mm = 0.0f;    // range mapped to the palette's start
  float far_mm = 8000.0f;  // range mapped to the palette's end
  bool fade_old_laps = true;
  friend bool operator==(const ColourParams&, const ColourParams&) = default;
};

// Motion mode's two colours: a hot one for what moves, a calm one for the room.
Rgba8 motion_colour(bool moving);

// What every point of a lap at `age` shares: its alpha (older laps fade) and, in lap-age mode, its
// hue (white otherwise). `age` is 0 for the newest lap and 1 for the oldest kept lap.
Rgba8 lap_look(const ColourParams& params, float age);

// `age` as lap_look's. In Motion mode the point is the
// room's unless `moving` says otherwise.
Rgba8 point_colour(const ColourParams& params, const LapPoint& point, float age, bool moving = false);

// Colour of an interference point the filter removed, drawn as a faint ghost when asked.
Rgba8 ghost_colour(PointFlag flag);

}  // namespace ydscope::ui
