#include "core/protocol/interference_filter.h"

namespace ydscope {

FilterCounts filter_interference(std::vector<LapPoint>& points, InterferenceFilter filter,
                                 std::vector<LapPoint>* removed) {
  FilterCounts counts;
  if (!filter.any()) return counts;
  std::size_t kept = 0;
  for (const LapPoint& point : points) {
    if (!filter.removes(point.flag)) {
      points[kept++] = point;
      continue;
    }
    ++(point.flag == PointFlag::Specular ? counts.specular : counts.ambient_light);
    if (removed) removed->push_back(point);
  }
  points.resize(kept);
  return counts;
}

}  // namespace ydscope
