#pragma once
// The Sources tab's Align: each lidar matched against the first of the list (core/align) from the
// pose it has now, and the answer held as a proposal the user applies or discards. Plain code,
// tested without a display.
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "core/frame/pose.h"
#include "core/protocol/lap.h"
#include "ui/view/scene/source_set.h"

namespace ydscope::ui {

struct AlignedSource {
  std::string text;          // "rear: 0.6,-0.4,35.01, residual 4.4 mm, 79 % overlap" or why not
  std::optional<Pose> pose;  // the pose found; empty for the reference and when refused
};

// One row per source, in list order; the first is the reference.
struct AlignmentProposal {
  std::vector<AlignedSource> rows;
  bool any_found() const;
};

// `laps[i]`: the recent laps of the source whose look is `looks[i]` (both in list order).
AlignmentProposal propose_alignment(std::span<const std::vector<Lap>> laps, std::span<const SourceLook> looks);

}  // namespace ydscope::ui
