#pragma once
// G1 interference filtering: points flagged specular reflection (flag 2) or ambient light (flag 3)
// can be dropped. A plain function over points, so the CLI, the app and tests share it; the
// removed points can be kept (e.g. to draw them as faint "ghosts").
#include <cstddef>
#include <vector>

#include "core/protocol/lap.h"

namespace ydscope {

struct InterferenceFilter {
  bool specular = false;
  bool ambient_light = false;

  bool any() const { return specular || ambient_light; }
  bool removes(PointFlag flag) const {
    return (specular && flag == PointFlag::Specular) || (ambient_light && flag == PointFlag::AmbientLight);
  }
};

struct FilterCounts {
  std::size_t specular = 0;
  std::size_t ambient_light = 0;
  std::size_t total() const { return specular + ambient_light; }
};

// Removes the points the filter selects from `points`, keeping the order of the rest. When
// `removed` is given, the removed points are appended to it in order. No allocation unless
// `removed` must grow.
FilterCounts filter_interference(std::vector<LapPoint>& points, InterferenceFilter filter,
                                 std::vector<LapPoint>* removed = nullptr);

inline FilterCounts filter_interference(Lap& lap, InterferenceFilter filter, std::vector<LapPoint>* removed = nullptr) {
  return filter_interference(lap.points, filter, removed);
}

}  // namespace ydscope
