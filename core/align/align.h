#pragma once
// Automatic alignment: where one lidar sits relative to a reference lidar, from several laps of
// each that see common walls. Steady points of each (steady_cloud), a correlative search for
// starts (coarse_search), point-to-line ICP from each start with trimmed pairs (line_icp), and a
// verdict that refuses rather than guess: too few points on common walls, walls that all run one
// way (a corridor: the shift along it is free), or two different fits nearly as good.
#include <cstddef>
#include <span>
#include <string>

#include "core/align/coarse_search.h"
#include "core/align/line_icp.h"
#include "core/align/steady_cloud.h"
#include "core/frame/pose.h"
#include "core/protocol/lap.h"

namespace ydscope::align {

struct AlignOptions {
  SteadyCloudOptions steady;
  CoarseOptions coarse;
  IcpOptions icp;
  double min_overlap = 0.3;             // share of the lidar's steady points on the reference's walls
  std::size_t min_pairs = 120;          // and at least this many
  double min_weakest_direction = 0.15;  // walls that run more than one way (see IcpFit)
  double ambiguous_share = 0.9;         // a distinct fit with this share of the best's pairs: ambiguous
};

enum class AlignVerdict { Aligned, NotEnoughOverlap, Ambiguous };

struct AlignResult {
  AlignVerdict verdict = AlignVerdict::NotEnoughOverlap;
  Pose pose;               // the lidar's pose in the reference's common frame (Aligned only)
  double residual_mm = 0;  // RMS point-to-line distance of the pairs used
  double overlap = 0;      // pairs / steady points, 0..1
  std::size_t pairs = 0;   // steady points of this lidar on the reference's walls
  std::size_t points = 0;  // steady points of this lidar
  std::size_t reference_points = 0;
  std::string message;  // one sentence: the numbers, and what to try when not aligned
};

// A pose as alignment reports it: millimetres and hundredths of a degree, what the match can tell
// and what a user types (no "-0").
Pose reported_pose(const Pose& pose);

// `lidar_laps` from the lidar at `start` (its rough pose: where to search from, within the
// coarse window), `reference_laps` from the reference at `reference_pose`. The flip of `start` is
// kept: alignment finds x, y and yaw.
AlignResult align_to_reference(std::span<const Lap> reference_laps, const Pose& reference_pose,
                               std::span<const Lap> lidar_laps, const Pose& start, const AlignOptions& options = {});

}  // namespace ydscope::align
