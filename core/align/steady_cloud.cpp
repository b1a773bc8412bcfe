#include "core/align/steady_cloud.h"

#include <algorithm>
#include <cmath>

namespace ydscope::align {

std::vector<LapPoint> steady_points(std::span<const Lap> laps, const SteadyCloudOptions& options) {
  std::vector<LapPoint> out;
  if (laps.size() < 2) return out;
  const auto bins = static_cast<std::size_t>(std::ceil(360.0 / options.bin_deg));
  struct Seen {
    float angle_deg;
    float range_mm;
  };
  std::vector<std::vector<Seen>> by_bin(bins);
  for (const Lap& lap : laps)
    for (const LapPoint& p : lap.points) {
      // Flagged points are a mirror's ghost or sunlight, not a surface where it seems to be.
      if (!(p.range_mm > 0.0f) || p.range_mm > options.max_range_mm || p.flag != PointFlag::None) continue;
      const auto bin = std::min(bins - 1, static_cast<std::size_t>(std::fmod(p.angle_deg, 360.0f) / options.bin_deg));
      by_bin[bin].push_back({p.angle_deg, p.range_mm});
    }
  const auto needed = static_cast<std::size_t>(std::ceil(options.agree_share * static_cast<double>(laps.size())));
  std::vector<float> ranges;
  for (const auto& seen : by_bin) {
    if (seen.size() < needed) continue;
    ranges.clear();
    for (const Seen& s : seen) ranges.push_back(s.range_mm);
    std::nth_element(ranges.begin(), ranges.begin() + static_cast<std::ptrdiff_t>(ranges.size() / 2), ranges.end());
    const double median = ranges[ranges.size() / 2];
    const double tolerance = options.agree_mm + options.agree_per_mm * median;
    double angle_sum = 0, range_sum = 0;
    std::size_t agreeing = 0;
    for (const Seen& s : seen)
      if (std::abs(s.range_mm - median) <= tolerance) {
        angle_sum += s.angle_deg;
        range_sum += s.range_mm;
        ++agreeing;
      }
    if (agreeing < needed) continue;  // something moves there, or the laps disagree
    out.push_back({static_cast<float>(angle_sum / static_cast<double>(agreeing)),
                   static_cast<float>(range_sum / static_cast<double>(agreeing)), PointFlag::None});
  }
  return out;
}

std::vector<Point2> to_common(std::span<const LapPoint> points, const Pose& pose) {
  std::vector<Point2> out;
  out.reserve(points.size());
  const PosedFrame frame(pose);
  for (const LapPoint& p : points) {
    const CommonPoint c = frame.to_common(p);
    out.push_back({c.x_mm, c.y_mm});
  }
  return out;
}

}  // namespace ydscope::align
