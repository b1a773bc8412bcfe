#pragma once
// What the view knows of each of several lidars shown at once: its name, colour and pose in the
// common frame, whether it is hidden or paused, and the one line its legend entry says. Plain
// code (no GL, no session), so the per-source state is tested without a display.
#include <cstddef>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "core/frame/pose.h"
#include "ui/view/geometry/geometry.h"
#include "ui/view/status/view_state.h"

namespace ydscope::ui {

struct SourceLook {
  std::string name;  // "G6", "front_left": the legend's and the selector's word for it
  Rgba8 colour;
  Pose pose;
  bool hidden = false;  // not drawn (its session still runs)
  bool paused = false;  // its picture holds its current laps
  // How to start it again in the next run (app/gui/source_origin.h spells it): "sim G6 demo",
  // "port detect /dev/ttyUSB0". Empty: it cannot be (a recording's replay).
  std::string origin;
  // The unit's serial (A5 90) it is bound to: a unit of this serial takes this name and pose on
  // whatever port it comes up (core/frame/unit_identity.h). settings.ini keeps it on a line of
  // its own, `unit = SERIAL; NAME`. Empty: bound by name and port only, as before serials.
  std::string serial;
  friend bool operator==(const SourceLook&, const SourceLook&) = default;
};

// The n-th source's colour: distinct hues that stay apart on the dark background, then round again.
Rgba8 source_colour(std::size_t index);
inline constexpr std::size_t kDistinctSourceColours = 8;

// The first colour of the palette none of `taken` has (a source added after one was removed gets
// the freed colour, never a second source's); round again when all are taken.
Rgba8 unused_source_colour(const std::vector<Rgba8>& taken);

// Where `count` lidars started together sit by default, so their clouds are told apart at a
// glance: one at the origin, two 4 m apart on a line, three or more on a circle of 3 m radius,
// each turned to face outwards a little differently.
std::vector<Pose> spread_poses(std::size_t count);

// Where a source added beside `taken` sits: the first of spread_poses(taken + 1) at least a metre
// from every taken position (a removed source leaves its place free), else the last.
Pose free_spread_pose(const std::vector<Pose>& taken);

// The legend's line for a source: "G6: scanning", "G6: no data 5 s, reconnecting",
// "G1: connecting". `seconds_since_lap` is empty when none has come yet.
std::string source_legend_line(std::string_view name, const ViewState& state, std::optional<double> seconds_since_lap);

// The name for a new source of `base` ("G6", "lidar") that none of `taken` has: G6, G6_2, G6_3...
std::string unique_source_name(std::string_view base, const std::vector<std::string>& taken);

// settings.ini's line for a remembered source: "NAME; X,Y,YAW[,flip]; #RRGGBB[; ORIGIN]" (the pose
// as --pose spells it). parse_source_line gives nothing and one sentence in `error` for a line it
// cannot read.
std::string format_source_line(const SourceLook& look);
std::optional<SourceLook> parse_source_line(std::string_view text, std::string& error);

}  // namespace ydscope::ui
