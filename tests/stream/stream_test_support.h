#pragma once
// Laps for the stream tests: each point carries the lap's index as its range, so a lap torn by a
// racing copy shows up as a mismatch.
#include <cstdint>

#include "core/protocol/lap.h"

namespace ydscope::test {

// `points` points; by default index % 300 + 1, which lap_is_consistent checks.
inline Lap indexed_lap(std::uint64_t index, std::size_t points) {
  Lap lap;
  lap.index = index;
  for (std::size_t i = 0; i < points; ++i)
    lap.points.push_back({static_cast<float>(i), static_cast<float>(index), PointFlag::None});
  return lap;
}
inline Lap indexed_lap(std::uint64_t index) { return indexed_lap(index, index % 300 + 1); }

inline bool lap_is_consistent(const Lap& lap) {
  for (const auto& point : lap.points)
    if (point.range_mm != static_cast<float>(lap.index)) return false;
  return lap.points.size() == lap.index % 300 + 1;
}

}  // namespace ydscope::test
