#include "core/frame/pose.h"

#include <array>
#include <charconv>
#include <cmath>
#include <numbers>
#include <vector>

#include "core/text/quoted_text.h"

namespace ydscope {
namespace {

std::optional<double> parse_number(std::string_view text) {
  double value = 0;
  const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (text.empty() || ec != std::errc() || end != text.data() + text.size() || !std::isfinite(value))
    return std::nullopt;
  return value;
}

std::string shortest(double value) {
  std::array<char, 32> buffer{};
  const auto [end, ec] = std::to_chars(buffer.data(), buffer.data() + buffer.size(), value);
  return ec == std::errc() ? std::string(buffer.data(), end) : std::string("0");
}

double radians(double degrees) { return degrees * std::numbers::pi / 180.0; }

}  // namespace

CommonPoint laser_point(const LapPoint& point) {
  const double a = radians(point.angle_deg);
  const double r = point.range_mm;
  return {static_cast<float>(-r * std::cos(a)), static_cast<float>(r * std::sin(a))};
}

CommonPoint Pose::to_common(const LapPoint& point) const { return to_common(laser_point(point)); }

PosedFrame::PosedFrame(const Pose& pose)
    : offset_cos_(std::cos(radians(pose.angle_offset_deg))),
      offset_sin_(std::sin(radians(pose.angle_offset_deg))),
      yaw_cos_(std::cos(radians(pose.yaw_deg))),
      yaw_sin_(std::sin(radians(pose.yaw_deg))),
      x_mm_(pose.x_m * 1000.0),
      y_mm_(pose.y_m * 1000.0),
      upside_down_(pose.upside_down) {}

CommonPoint PosedFrame::to_common(CommonPoint laser) const {
  // The offset adds to the unit's clockwise angles: a turn by -offset in the laser frame.
  const double ox = laser.x_mm * offset_cos_ + laser.y_mm * offset_sin_;
  const double oy = -laser.x_mm * offset_sin_ + laser.y_mm * offset_cos_;
  // The upside-down mount rolls about the laser's x axis: y -> -y (a -> 360 - a).
  const double lx = ox;
  const double ly = upside_down_ ? -oy : oy;
  return {static_cast<float>(lx * yaw_cos_ - ly * yaw_sin_ + x_mm_),
          static_cast<float>(lx * yaw_sin_ + ly * yaw_cos_ + y_mm_)};
}

CommonPoint Pose::to_common(CommonPoint laser) const { return PosedFrame(*this).to_common(laser); }

void Pose::to_common(const Lap& lap, std::vector<CommonPoint>& out) const {
  const PosedFrame frame(*this);
  out.resize(lap.points.size());
  for (std::size_t i = 0; i < lap.points.size(); ++i) out[i] = frame.to_common(lap.points[i]);
}

CommonPoint Pose::to_laser(CommonPoint common) const {
  const double dx = static_cast<double>(common.x_mm) - x_m * 1000.0;
  const double dy = static_cast<double>(common.y_mm) - y_m * 1000.0;
  const double c = std::cos(radians(yaw_deg));
  const double s = std::sin(radians(yaw_deg));
  const double lx = dx * c + dy * s;
  const double ly = upside_down ? -(-dx * s + dy * c) : -dx * s + dy * c;
  const double oc = std::cos(radians(angle_offset_deg));
  const double os = std::sin(radians(angle_offset_deg));
  return {static_cast<float>(lx * oc - ly * os), static_cast<float>(lx * os + ly * oc)};
}

std::optional<Pose> parse_pose(std::string_view text, std::string& error) {
  const std::string shown = quote_file_text(text);  // a recording's pose may hold any bytes
  std::vector<std::string_view> fields;
  for (std::size_t start = 0;;) {
    const std::size_t comma = text.find(',', start);
    fields.push_back(text.substr(start, comma == std::string_view::npos ? std::string_view::npos : comma - start));
    if (comma == std::string_view::npos) break;
    start = comma + 1;
  }
  if (fields.size() < 3 || fields.size() > 5) {
    error = "a pose is x,y,yaw[,flip][,offset=DEG] (metres, metres, degrees), such as 0.2,-0.15,90, not " + shown;
    return std::nullopt;
  }
  const auto x = parse_number(fields[0]);
  const auto y = parse_number(fields[1]);
  const auto yaw = parse_number(fields[2]);
  if (!x || !y || !yaw) {
    error = "a pose's x, y and yaw are numbers (metres, metres, degrees), such as 0.2,-0.15,90, not " + shown;
    return std::nullopt;
  }
  if (std::abs(*x) > kMaxPoseOffsetM || std::abs(*y) > kMaxPoseOffsetM) {
    error = "a pose's x and y are metres, within " + shortest(kMaxPoseOffsetM) + " of the origin, not " + shown +
            " (millimetres given as metres?)";
    return std::nullopt;
  }
  if (std::abs(*yaw) > 360.0) {
    error = "a pose's yaw is degrees from -360 to 360, not " + shown;
    return std::nullopt;
  }
  Pose pose{*x, *y, *yaw, false, 0.0};
  bool offset_given = false;
  for (std::size_t i = 3; i < fields.size(); ++i) {
    constexpr std::string_view kOffset = "offset=";
    if (fields[i] == "flip" && !pose.upside_down) {
      pose.upside_down = true;
    } else if (fields[i].substr(0, kOffset.size()) == kOffset && !offset_given) {
      const auto offset = parse_number(fields[i].substr(kOffset.size()));
      if (!offset || std::abs(*offset) > 360.0) {
        error = "a pose's offset= is degrees from -360 to 360, not " + shown;
        return std::nullopt;
      }
      pose.angle_offset_deg = *offset;
      offset_given = true;
    } else {
      error =
          "after a pose's yaw come only flip (mounted upside down) and offset=DEG (the unit's angle offset), "
          "each once, not " +
          shown;
      return std::nullopt;
    }
  }
  return pose;
}

std::string format_pose(const Pose& pose) {
  return shortest(pose.x_m) + "," + shortest(pose.y_m) + "," + shortest(pose.yaw_deg) +
         (pose.upside_down ? ",flip" : "") +
         (pose.angle_offset_deg != 0.0 ? ",offset=" + shortest(pose.angle_offset_deg) : "");
}

}  // namespace ydscope
