#include "core/align/line_map.h"

#include <cmath>

#include "core/align/spread.h"

namespace ydscope::align {
namespace {

constexpr double kCellMm = 100.0;
constexpr int kNeighbours = 4;               // each side, in scan order
constexpr double kNeighbourReachMm = 250.0;  // farther is another object, or a gap
constexpr double kMaxFlatness = 0.05;        // smaller / larger spread: a straight run, not a corner or a leg

long long cell_of(double mm) { return static_cast<long long>(std::floor(mm / kCellMm)); }

}  // namespace

LineMap::LineMap(std::span<const Point2> points) {
  const auto n = static_cast<long long>(points.size());
  for (long long i = 0; i < n; ++i) {
    const Point2 p = points[static_cast<std::size_t>(i)];
    double sx = 0, sy = 0;
    int count = 0;
    std::vector<Point2> run;
    for (long long j = i - kNeighbours; j <= i + kNeighbours; ++j) {
      const Point2 q = points[static_cast<std::size_t>((j % n + n) % n)];  // the scan closes on itself
      if (std::hypot(q.x - p.x, q.y - p.y) > kNeighbourReachMm) continue;
      run.push_back(q);
      sx += q.x;
      sy += q.y;
      ++count;
    }
    if (count < 5) continue;
    const double mx = sx / count, my = sy / count;
    Spread spread;
    for (const Point2& q : run) spread.add(q.x - mx, q.y - my);
    // The normal is the direction of the smaller eigenvalue.
    const double large = spread.larger(), small = spread.smaller();
    const double xx = spread.xx, xy = spread.xy, yy = spread.yy;
    if (!(large > 0) || small / large > kMaxFlatness) continue;
    // Eigenvector of `small`: (xy, small - xx), or (small - yy, xy), whichever is the larger.
    Point2 normal{xy, small - xx};
    if (std::hypot(normal.x, normal.y) < 1e-9) normal = {small - yy, xy};
    const double length = std::hypot(normal.x, normal.y);
    if (length < 1e-9) continue;
    lines_.push_back({p, {normal.x / length, normal.y / length}});
    cells_[key(cell_of(p.x), cell_of(p.y))].push_back(lines_.size() - 1);
  }
}

std::optional<LinePoint> LineMap::nearest(Point2 p, double max_mm) const {
  const long long reach = static_cast<long long>(std::ceil(max_mm / kCellMm));
  const long long cx = cell_of(p.x), cy = cell_of(p.y);
  double best = max_mm * max_mm;
  std::optional<LinePoint> found;
  for (long long dx = -reach; dx <= reach; ++dx)
    for (long long dy = -reach; dy <= reach; ++dy) {
      const auto it = cells_.find(key(cx + dx, cy + dy));
      if (it == cells_.end()) continue;
      for (const std::size_t index : it->second) {
        const LinePoint& line = lines_[index];
        const double d2 = (line.at.x - p.x) * (line.at.x - p.x) + (line.at.y - p.y) * (line.at.y - p.y);
        if (d2 <= best) {
          best = d2;
          found = line;
        }
      }
    }
  return found;
}

}  // namespace ydscope::align
