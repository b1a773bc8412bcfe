#pragma once
// A named zone round the robot and the rule it is watched by: a sector with an optional range band
// in the lidar's own angles, or a polygon in the robot's frame (REP-103: x forward, y left, as
// core/frame/pose.h). The app colours it, `serve` publishes it on /zones and /diagnostics, and the
// same text form is given on the command line (--zone) and kept in settings.ini (zone = ...):
//
//   NAME:sector:FROM:TO[:MIN_MM:MAX_MM][:RULE]     e.g.  front:sector:150:210:0:1500
//   NAME:polygon:X,Y/X,Y/X,Y[/...][:RULE]          e.g.  dock:polygon:0.5,-0.3/1.2,-0.3/1.2,0.3/0.5,0.3:empty
//
// Angles in degrees as the lidar reports them (clockwise, may cross 0), the band in millimetres,
// polygon corners in metres in the robot's frame. RULE is `enter` (the default: the zone should be
// clear, and something in it raises it) or `empty` (something should be there, a dock or a pallet,
// and its absence raises it).
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "core/analysis/sector.h"
#include "core/frame/pose.h"

namespace ydscope {

enum class ZoneRule : std::uint8_t { Enter, Empty };

struct Zone {
  std::string name;
  std::optional<Sector> sector;      // the lidar's angles and range band ...
  std::vector<CommonPoint> polygon;  // ... or corners in the robot's frame, mm
  ZoneRule rule = ZoneRule::Enter;

  // A return of the lidar posed at `pose` lies in the zone (points without a return never do).
  bool contains(const LapPoint& point, const PosedFrame& pose) const;
};

// Parses the text form above. Empty plus one sentence in `error` that says what was wrong.
std::optional<Zone> parse_zone(std::string_view spec, std::string& error);
// The text form again; parse_zone(zone_spec(z)) gives the same zone.
std::string zone_spec(const Zone& zone);
const char* zone_rule_name(ZoneRule rule);  // "enter", "empty"

// The syntax in one line, for usage errors and --help.
inline constexpr std::string_view kZoneSyntax =
    "NAME:sector:FROM:TO[:MIN_MM:MAX_MM][:enter|empty] or NAME:polygon:X,Y/X,Y/X,Y[/...][:enter|empty] (metres, "
    "robot frame)";

}  // namespace ydscope
