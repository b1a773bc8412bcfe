#include "core/analysis/zone.h"

#include <cctype>
#include <charconv>
#include <cmath>
#include <cstdio>

namespace ydscope {

namespace {

std::vector<std::string_view> split(std::string_view text, char separator) {
  std::vector<std::string_view> parts;
  std::size_t start = 0;
  for (std::size_t at = text.find(separator); at != std::string_view::npos; at = text.find(separator, start)) {
    parts.push_back(text.substr(start, at - start));
    start = at + 1;
  }
  parts.push_back(text.substr(start));
  return parts;
}

std::optional<double> number(std::string_view text) {
  double value = 0;
  const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (text.empty() || ec != std::errc() || end != text.data() + text.size() || !std::isfinite(value))
    return std::nullopt;
  return value;
}

bool valid_name(std::string_view name) {
  if (name.empty() || name.size() > 32) return false;
  for (const char c : name)
    if (!(std::isalnum(static_cast<unsigned char>(c)) || c == '_' || c == '-')) return false;
  return true;
}

std::optional<ZoneRule> rule_of(std::string_view text) {
  if (text == "enter") return ZoneRule::Enter;
  if (text == "empty") return ZoneRule::Empty;
  return std::nullopt;
}

// Twice the signed area: zero for corners on one line.
double doubled_area(const std::vector<CommonPoint>& p) {
  double a = 0;
  for (std::size_t i = 0, j = p.size() - 1; i < p.size(); j = i++)
    a += static_cast<double>(p[j].x_mm) * p[i].y_mm - static_cast<double>(p[i].x_mm) * p[j].y_mm;
  return a;
}

bool inside_polygon(const std::vector<CommonPoint>& p, CommonPoint q) {
  bool inside = false;  // even-odd rule: crossings of a ray towards +x
  for (std::size_t i = 0, j = p.size() - 1; i < p.size(); j = i++) {
    if ((p[i].y_mm > q.y_mm) == (p[j].y_mm > q.y_mm)) continue;
    const float x_at = p[j].x_mm + (q.y_mm - p[j].y_mm) * (p[i].x_mm - p[j].x_mm) / (p[i].y_mm - p[j].y_mm);
    if (q.x_mm < x_at) inside = !inside;
  }
  return inside;
}

std::optional<std::vector<CommonPoint>> parse_corners(std::string_view text, std::string& error) {
  std::vector<CommonPoint> corners;
  for (std::string_view corner : split(text, '/')) {
    const auto xy = split(corner, ',');
    const auto x = xy.size() == 2 ? number(xy[0]) : std::nullopt;
    const auto y = xy.size() == 2 ? number(xy[1]) : std::nullopt;
    if (!x || !y || std::fabs(*x) > kMaxPoseOffsetM || std::fabs(*y) > kMaxPoseOffsetM) {
      error = "a polygon corner is X,Y in metres, such as 0.5,-0.3, not '" + std::string(corner) + "'";
      return std::nullopt;
    }
    corners.push_back({static_cast<float>(*x * 1000.0), static_cast<float>(*y * 1000.0)});
  }
  if (corners.size() < 3 || std::fabs(doubled_area(corners)) < 1.0) {
    error = "a polygon needs at least three corners that are not on one line, separated by '/'";
    return std::nullopt;
  }
  return corners;
}

}  // namespace

const char* zone_rule_name(ZoneRule rule) { return rule == ZoneRule::Empty ? "empty" : "enter"; }

bool Zone::contains(const LapPoint& point, const PosedFrame& pose) const {
  if (point.range_mm <= 0.0f) return false;
  if (sector) return sector->contains(point);
  return inside_polygon(polygon, pose.to_common(point));
}

std::optional<Zone> parse_zone(std::string_view spec, std::string& error) {
  const auto fail = [&](const std::string& why) -> std::optional<Zone> {
    error = "zone '" + std::string(spec) + "': " + why + "; a zone is " + std::string(kZoneSyntax);
    return std::nullopt;
  };
  std::vector<std::string_view> parts = split(spec, ':');
  if (parts.size() < 3) return fail("too few parts");
  Zone zone;
  zone.name = std::string(parts[0]);
  if (!valid_name(parts[0])) return fail("its name must be 1 to 32 letters, digits, _ or -");
  if (const auto rule = rule_of(parts.back()); rule && parts.size() > 3) {
    zone.rule = *rule;
    parts.pop_back();
  }
  std::string why;
  if (parts[1] == "sector") {
    if (parts.size() != 4 && parts.size() != 6) return fail("a sector is FROM:TO, optionally then MIN_MM:MAX_MM");
    zone.sector = parse_sector(std::string(parts[2]) + ":" + std::string(parts[3]), why);
    if (!zone.sector) return fail(why);
    if (parts.size() == 6 && !set_range_band(*zone.sector, std::string(parts[4]) + ":" + std::string(parts[5]), why))
      return fail(why);
  } else if (parts[1] == "polygon") {
    if (parts.size() != 3) return fail("a polygon is its corners X,Y/X,Y/X,Y, then optionally the rule");
    auto corners = parse_corners(parts[2], why);
    if (!corners) return fail(why);
    zone.polygon = std::move(*corners);
  } else {
    return fail("the shape is sector or polygon, not '" + std::string(parts[1]) + "'");
  }
  return zone;
}

std::string zone_spec(const Zone& zone) {
  std::string text = zone.name;
  char number_text[64];
  if (zone.sector) {
    std::snprintf(number_text, sizeof number_text, ":sector:%g:%g", zone.sector->from_deg, zone.sector->to_deg);
    text += number_text;
    if (zone.sector->min_mm && zone.sector->max_mm) {
      std::snprintf(number_text, sizeof number_text, ":%g:%g", *zone.sector->min_mm, *zone.sector->max_mm);
      text += number_text;
    }
  } else {
    text += ":polygon:";
    for (std::size_t i = 0; i < zone.polygon.size(); ++i) {
      std::snprintf(number_text, sizeof number_text, "%s%g,%g", i ? "/" : "", zone.polygon[i].x_mm / 1000.0,
                    zone.polygon[i].y_mm / 1000.0);
      text += number_text;
    }
  }
  return text + ":" + zone_rule_name(zone.rule);
}

}  // namespace ydscope
