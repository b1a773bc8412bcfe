#include "core/analysis/sector.h"

#include <charconv>
#include <cmath>
#include <cstdio>

namespace ydscope {

namespace {

double wrap_degrees(double degrees) {
  const double wrapped = std::fmod(degrees, 360.0);
  return wrapped < 0 ? wrapped + 360.0 : wrapped;
}

std::optional<double> parse_number(std::string_view text) {
  double value = 0;
  const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (ec != std::errc() || end != text.data() + text.size() || !std::isfinite(value)) return std::nullopt;
  return value;
}

}  // namespace

double Sector::width_deg() const {
  const double width = wrap_degrees(to_deg - from_deg);
  return width == 0 ? 360.0 : width;
}

double Sector::centre_deg() const { return wrap_degrees(from_deg + 0.5 * width_deg()); }

double Sector::offset_deg(double angle_deg) const { return wrap_degrees(angle_deg - from_deg); }

bool Sector::contains(const LapPoint& point) const {
  if (!contains_angle(point.angle_deg)) return false;
  if (point.range_mm <= 0.0f) return true;
  if (min_mm && point.range_mm < *min_mm) return false;
  if (max_mm && point.range_mm > *max_mm) return false;
  return true;
}

std::optional<Sector> parse_sector(std::string_view text, std::string& error) {
  const auto colon = text.find(':');
  const auto from = colon == std::string_view::npos ? std::nullopt : parse_number(text.substr(0, colon));
  const auto to = colon == std::string_view::npos ? std::nullopt : parse_number(text.substr(colon + 1));
  if (!from || !to) {
    error = "a sector is FROM:TO in degrees, such as 260:280 or 350:10, not '" + std::string(text) + "'";
    return std::nullopt;
  }
  if (*from < 0 || *from > 360 || *to < 0 || *to > 360) {
    error = "sector angles must be within 0 to 360 degrees, not '" + std::string(text) + "'";
    return std::nullopt;
  }
  if (wrap_degrees(*from) == wrap_degrees(*to)) {
    error = "a sector needs two different angles ('" + std::string(text) + "' is empty or the whole circle)";
    return std::nullopt;
  }
  Sector sector;
  sector.name = std::string(text);
  sector.from_deg = wrap_degrees(*from);
  sector.to_deg = wrap_degrees(*to);
  return sector;
}

bool set_range_band(Sector& sector, std::string_view text, std::string& error) {
  const auto colon = text.find(':');
  const auto lo = colon == std::string_view::npos ? std::nullopt : parse_number(text.substr(0, colon));
  const auto hi = colon == std::string_view::npos ? std::nullopt : parse_number(text.substr(colon + 1));
  if (!lo || !hi) {
    error = "a range band is MIN:MAX in mm, such as 1500:2500, not '" + std::string(text) + "'";
    return false;
  }
  if (*lo < 0 || *hi <= *lo) {
    error = "a range band needs 0 <= MIN < MAX, not '" + std::string(text) + "'";
    return false;
  }
  sector.min_mm = *lo;
  sector.max_mm = *hi;
  sector.name += " (" + std::string(text) + " mm)";
  return true;
}

std::optional<Sector> parse_sector_spec(std::string_view spec, std::string& error) {
  const auto space = spec.find(' ');
  std::optional<Sector> sector = parse_sector(spec.substr(0, space), error);
  if (!sector || space == std::string_view::npos) return sector;
  if (!set_range_band(*sector, spec.substr(space + 1), error)) return std::nullopt;
  return sector;
}

std::string sector_spec(const Sector& s) {
  char text[96];
  if (s.min_mm && s.max_mm)
    std::snprintf(text, sizeof text, "%g:%g %g:%g", s.from_deg, s.to_deg, *s.min_mm, *s.max_mm);
  else
    std::snprintf(text, sizeof text, "%g:%g", s.from_deg, s.to_deg);
  return text;
}

}  // namespace ydscope
