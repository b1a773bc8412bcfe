#pragma once
// The fine step: point-to-line ICP. Each moving point is paired with the nearest piece of
// reference wall; the turn and shift that minimise the squared distances along the walls'
// normals are solved in closed form (small-angle linearisation, a 3x3 system) and applied
// exactly, over and over. Outliers (a person, a corner, a piece of wall only one lidar sees) are
// trimmed: only the best share of the pairs counts in each round.
#include <cstddef>
#include <span>

#include "core/align/line_map.h"
#include "core/align/rigid_motion.h"

namespace ydscope::align {

struct IcpOptions {
  std::size_t max_rounds = 60;
  double first_gate_mm = 300;  // pairs farther apart than the gate are not pairs
  double last_gate_mm = 60;    // the gate shrinks to this as the fit settles
  double keep_share = 0.8;     // trimmed: the best 80 % of pairs count
};

struct IcpFit {
  RigidMotion motion;
  std::size_t pairs = 0;  // within the last gate after the last round
  double rms_mm = 0;      // of those pairs' point-to-line distances
  // How firmly the pairs' walls pin each direction of shift: the smaller eigenvalue of the
  // sum of n n^T, per pair (1 when walls run every way equally, 0 when all run one way).
  double weakest_direction = 0;
};

// From `start` (a motion of `moving`, about its centre), to where the pairs stop moving.
IcpFit refine(const LineMap& reference, std::span<const Point2> moving, const RigidMotion& start,
              const IcpOptions& options = {});

}  // namespace ydscope::align
