#pragma once
// The coarse step: a correlative search that tries every turn and shift within a window on a
// smoothed picture of the reference cloud and keeps the best few distinct ones. It needs no
// good start (ICP alone falls into the nearest wrong wall from 30 degrees off), and the several
// winners are the starts ICP refines.
#include <cstddef>
#include <span>
#include <vector>

#include "core/align/rigid_motion.h"

namespace ydscope::align {

struct CoarseOptions {
  double window_turn_deg = 45;  // either way from the start
  double window_shift_mm = 1000;
  double turn_step_deg = 1;
  double cell_mm = 40;           // the shift step, too
  double blur_mm = 60;           // how far from a reference point a point still scores
  std::size_t keep = 6;          // distinct candidates handed to ICP
  std::size_t max_points = 400;  // of the moving cloud, evenly taken
};

struct Candidate {
  RigidMotion motion;
  double score = 0;  // share of the moving points on the reference, 0..1 (blurred)
};

// The best distinct motions of `moving` (common frame at its start pose, turned about `centre`,
// the lidar's position) onto `reference`, best first.
std::vector<Candidate> coarse_search(std::span<const Point2> reference, std::span<const Point2> moving, Point2 centre,
                                     const CoarseOptions& options = {});

}  // namespace ydscope::align
