#include "core/analysis/blockage_criterion.h"

#include "core/analysis/text_format.h"

namespace ydscope {

CriterionResult blockage_criterion(const std::vector<BlockedSector>& blocked, const DropoutOptions& options) {
  CriterionResult r{
      "blockage",
      "blocked sectors",
      blocked.empty() ? "none" : describe_blocked_sectors(blocked),
      format_text("no sector of %.0f° or more without returns (at least %.0f %% empty over %.0f s) "
                  "while the rest of the turn sees them",
                  options.min_width_deg, 100.0 * options.blocked_share, static_cast<double>(options.window_ns) * 1e-9),
      blocked.empty() ? Verdict::Pass : Verdict::Fail,
      static_cast<double>(blocked.size())};
  return r;
}

}  // namespace ydscope
