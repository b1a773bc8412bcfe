#pragma once
// A region of the scan to measure: an angular sector, optionally narrowed to a band of ranges.
// Angles follow the lap's (corrected, [0, 360)); a sector runs from `from_deg` up to `to_deg` and
// may cross 0 ("350:10" is 20 degrees wide).
#include <optional>
#include <string>
#include <string_view>

#include "core/protocol/lap.h"

namespace ydscope {

struct Sector {
  std::string name;
  double from_deg = 0;
  double to_deg = 0;
  // Range band: points with a return outside it belong to something else (the background behind
  // a target) and are left out; points without a return still count, as misses.
  std::optional<double> min_mm;
  std::optional<double> max_mm;

  // (to - from) wrapped into (0, 360]; equal ends mean the whole circle.
  double width_deg() const;
  double centre_deg() const;
  // How far past from_deg the angle lies, wrapped into [0, 360).
  double offset_deg(double angle_deg) const;
  bool contains_angle(double angle_deg) const { return offset_deg(angle_deg) < width_deg(); }
  // In the sector's angles and not a return outside the band.
  bool contains(const LapPoint& point) const;
};

// A return the lidar did not mark as suspect: a range, and no G1 interference flag (specular,
// ambient light). G6/TG points carry no flags, so there any range counts.
inline bool is_valid_return(const LapPoint& point) {
  return point.range_mm > 0.0f && point.flag != PointFlag::Specular && point.flag != PointFlag::AmbientLight;
}

// Parses "A:B" in degrees (each in [0, 360], A != B). Empty plus one sentence in `error` on a mistake.
std::optional<Sector> parse_sector(std::string_view text, std::string& error);

// Narrows `sector` to returns "MIN:MAX" mm away (0 <= MIN < MAX) and names the band in its name.
// False plus one sentence in `error` on a mistake.
bool set_range_band(Sector& sector, std::string_view text, std::string& error);

// "FROM:TO" in degrees, optionally followed by " MIN:MAX" in mm (the app's --sector and its
// settings.ini); sector_spec() writes it back. Empty plus one sentence in `error` on a mistake.
std::optional<Sector> parse_sector_spec(std::string_view spec, std::string& error);
std::string sector_spec(const Sector& sector);

}  // namespace ydscope
