#pragma once
// The reference lidar's cloud as short pieces of wall: each steady point that lies on a straight
// run of its neighbours gets that run's normal, so another cloud can be matched point to line
// (a point may slide along a wall without cost, which is what makes point-to-line ICP converge
// from farther away than point to point). Found by a grid, as clouds here are a few thousand
// points: a k-d tree (nanoflann) would not pay for itself.
#include <cstddef>
#include <optional>
#include <span>
#include <unordered_map>
#include <vector>

#include "core/align/rigid_motion.h"

namespace ydscope::align {

struct LinePoint {
  Point2 at;
  Point2 normal;  // unit
};

class LineMap {
 public:
  // `points` in scan order (neighbours in the order are neighbours on the wall).
  explicit LineMap(std::span<const Point2> points);

  std::size_t size() const { return lines_.size(); }
  // The nearest wall piece within max_mm of p, or none.
  std::optional<LinePoint> nearest(Point2 p, double max_mm) const;

 private:
  long long key(long long cx, long long cy) const { return cx * 1'000'003LL + cy; }
  std::vector<LinePoint> lines_;
  std::unordered_map<long long, std::vector<std::size_t>> cells_;
};

}  // namespace ydscope::align
