#pragma once
// The `check` criterion "blocked sectors": the run fails when a sector of the turn stayed empty
// while the rest saw returns (core/analysis/dropout_ring.h), and says which, in the sentence the
// app and /diagnostics use ("blocked 40°–75° for 12 s").
#include <vector>

#include "core/analysis/acceptance.h"
#include "core/analysis/dropout_ring.h"

namespace ydscope {

CriterionResult blockage_criterion(const std::vector<BlockedSector>& blocked, const DropoutOptions& options);

}  // namespace ydscope
