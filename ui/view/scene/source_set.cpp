#include "ui/view/scene/source_set.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>

namespace ydscope::ui {

Rgba8 source_colour(std::size_t index) {
  // Hues far apart and bright enough on the near-black view; the first three are the ones a
  // three-lidar robot or bench shows, so they are the most distinct (orange, cyan, magenta).
  static constexpr std::array<Rgba8, kDistinctSourceColours> kColours{{
      {255, 150, 40, 255},   // orange
      {60, 210, 255, 255},   // cyan
      {235, 80, 220, 255},   // magenta
      {130, 230, 80, 255},   // green
      {255, 235, 90, 255},   // yellow
      {150, 130, 255, 255},  // violet
      {255, 110, 110, 255},  // coral
      {200, 200, 200, 255},  // grey
  }};
  return kColours[index % kColours.size()];
}

Rgba8 unused_source_colour(const std::vector<Rgba8>& taken) {
  for (std::size_t i = 0; i < kDistinctSourceColours; ++i)
    if (std::find(taken.begin(), taken.end(), source_colour(i)) == taken.end()) return source_colour(i);
  return source_colour(taken.size());
}

Pose free_spread_pose(const std::vector<Pose>& taken) {
  const std::vector<Pose> spread = spread_poses(taken.size() + 1);
  for (const Pose& candidate : spread) {
    const bool free = std::none_of(taken.begin(), taken.end(), [&](const Pose& p) {
      return std::hypot(p.x_m - candidate.x_m, p.y_m - candidate.y_m) < 1.0;
    });
    if (free) return candidate;
  }
  return spread.back();
}

std::vector<Pose> spread_poses(std::size_t count) {
  std::vector<Pose> poses(count);
  if (count == 2) {  // one on the left facing back, one on the right facing forward
    poses[0].y_m = 2.0;
    poses[0].yaw_deg = 180.0;
    poses[1].y_m = -2.0;
  } else if (count >= 3) {
    constexpr double kRadiusM = 3.0;
    for (std::size_t i = 0; i < count; ++i) {
      // Evenly round a circle clockwise seen from above, the first straight ahead of the origin.
      const double turn = 360.0 * static_cast<double>(i) / static_cast<double>(count);
      const double rad = turn * 3.14159265358979 / 180.0;
      poses[i].x_m = std::round(kRadiusM * std::cos(rad) * 100.0) / 100.0 + 0.0;
      poses[i].y_m = std::round(-kRadiusM * std::sin(rad) * 100.0) / 100.0 + 0.0;
      // Each faces its own way, so the clouds differ in shape too; within (-180, 180], never -0.
      const double yaw = 180.0 - turn;
      poses[i].yaw_deg = (yaw <= -180.0 ? yaw + 360.0 : yaw) + 0.0;
    }
  }
  return poses;
}

std::string source_legend_line(std::string_view name, const ViewState& state, std::optional<double> seconds_since_lap) {
  std::string line = std::string(name) + ": ";
  if (state.live) return line + state.status;
  // How long nothing came says more than "no data" alone; the link's own state follows.
  if (seconds_since_lap) {
    // Under a second "0 s" reads as a glitch; the age counts up from 1 s.
    line += *seconds_since_lap >= 1.0 ? "no data " + format_age(*seconds_since_lap) : std::string("no data");
    if (state.status != "no data") line += ", " + state.status;
    return line;
  }
  return line + state.status;
}

std::string unique_source_name(std::string_view base, const std::vector<std::string>& taken) {
  const auto free = [&](const std::string& name) { return std::find(taken.begin(), taken.end(), name) == taken.end(); };
  std::string name(base.empty() ? std::string_view("lidar") : base);
  if (free(name)) return name;
  for (int n = 2;; ++n)
    if (const std::string candidate = name + "_" + std::to_string(n); free(candidate)) return candidate;
}

std::string format_source_line(const SourceLook& look) {
  char colour[8];
  std::snprintf(colour, sizeof colour, "#%02X%02X%02X", look.colour.r, look.colour.g, look.colour.b);
  // A pose set by mouse carries float noise: a millimetre and a hundredth of a degree are plenty.
  Pose rounded = look.pose;
  rounded.x_m = std::round(rounded.x_m * 1000.0) / 1000.0;
  rounded.y_m = std::round(rounded.y_m * 1000.0) / 1000.0;
  rounded.yaw_deg = std::round(rounded.yaw_deg * 100.0) / 100.0 + 0.0;  // + 0.0: no "-0"
  return look.name + "; " + format_pose(rounded) + "; " + colour + (look.origin.empty() ? "" : "; " + look.origin);
}

std::optional<SourceLook> parse_source_line(std::string_view text, std::string& error) {
  const auto trim = [](std::string_view v) {
    while (!v.empty() && v.front() == ' ') v.remove_prefix(1);
    while (!v.empty() && v.back() == ' ') v.remove_suffix(1);
    return v;
  };
  const std::size_t first = text.find(';');
  const std::size_t second = first == std::string_view::npos ? first : text.find(';', first + 1);
  if (second == std::string_view::npos) {
    error = "expected NAME; X,Y,YAW; #RRGGBB";
    return std::nullopt;
  }
  SourceLook look;
  look.name = std::string(trim(text.substr(0, first)));
  if (look.name.empty() || look.name.find_first_of(" \t") != std::string::npos) {
    error = "the name is empty or holds spaces";
    return std::nullopt;
  }
  const auto pose = parse_pose(trim(text.substr(first + 1, second - first - 1)), error);
  if (!pose) return std::nullopt;
  look.pose = *pose;
  const std::size_t third = text.find(';', second + 1);
  const std::string_view hex =
      trim(text.substr(second + 1, third == std::string_view::npos ? third : third - second - 1));
  if (third != std::string_view::npos) look.origin = std::string(trim(text.substr(third + 1)));
  unsigned r = 0, g = 0, b = 0;
  char tail = 0;
  if (hex.size() != 7 || std::sscanf(std::string(hex).c_str(), "#%2x%2x%2x%c", &r, &g, &b, &tail) != 3) {
    error = "the colour '" + std::string(hex) + "' is not #RRGGBB";
    return std::nullopt;
  }
  look.colour = {static_cast<std::uint8_t>(r), static_cast<std::uint8_t>(g), static_cast<std::uint8_t>(b), 255};
  return look;
}

}  // namespace ydscope::ui
