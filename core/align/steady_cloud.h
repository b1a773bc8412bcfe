#pragma once
// What alignment matches: the points a lidar sees the same way lap after lap. Several laps are
// folded per direction into the median range, and a direction counts only when most laps agree on
// it: people walking, a mirror's ghosts and sunlight's spots (flagged) and single stray returns
// drop out, and the walls' noise shrinks.
#include <span>
#include <vector>

#include "core/align/rigid_motion.h"
#include "core/frame/pose.h"
#include "core/protocol/lap.h"

namespace ydscope::align {

struct SteadyCloudOptions {
  double bin_deg = 0.5;          // directions folded together
  double max_range_mm = 15'000;  // farther returns are too sparse and noisy to pin a pose
  double agree_share = 0.6;      // of the laps must see a direction within the tolerance below
  double agree_mm = 40;          // ... of its median, plus agree_per_mm of the range
  double agree_per_mm = 0.01;
};

// The steady points of `laps` (all of one lidar) in its own device terms (angle, median range), in
// angle order. Fewer than two laps give no points: nothing can be said to stay.
std::vector<LapPoint> steady_points(std::span<const Lap> laps, const SteadyCloudOptions& options = {});

// Those points in the common frame at `pose`, in the same order.
std::vector<Point2> to_common(std::span<const LapPoint> points, const Pose& pose);

}  // namespace ydscope::align
