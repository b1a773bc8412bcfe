#include "ui/view/scene/source_alignment.h"

#include <algorithm>
#include <cstdio>

#include "core/align/align.h"

namespace ydscope::ui {

bool AlignmentProposal::any_found() const {
  return std::any_of(rows.begin(), rows.end(), [](const AlignedSource& row) { return row.pose.has_value(); });
}

AlignmentProposal propose_alignment(std::span<const std::vector<Lap>> laps, std::span<const SourceLook> looks) {
  AlignmentProposal proposal;
  if (looks.empty() || laps.size() != looks.size()) return proposal;
  proposal.rows.push_back({looks[0].name + ": the reference, stays at " + format_pose(looks[0].pose), std::nullopt});
  for (std::size_t i = 1; i < looks.size(); ++i) {
    const align::AlignResult r = align::align_to_reference(laps[0], looks[0].pose, laps[i], looks[i].pose);
    if (r.verdict != align::AlignVerdict::Aligned) {
      proposal.rows.push_back({looks[i].name + ": " + r.message, std::nullopt});
      continue;
    }
    const Pose pose = align::reported_pose(r.pose);
    char numbers[96];
    std::snprintf(numbers, sizeof numbers, ", residual %.1f mm, %.0f %% overlap", r.residual_mm, 100.0 * r.overlap);
    proposal.rows.push_back({looks[i].name + ": " + format_pose(pose) + numbers, pose});
  }
  return proposal;
}

}  // namespace ydscope::ui
