#pragma once
// `ydscope-cli check` with two or more --port: every lidar checked at once over one run, each by
// run_check on a thread of its own with a session of its own (as one unit is checked), so a slow or
// dead unit holds up none of the others. Each unit gets its verdict under its name and, with
// --reports DIR, a report of its own named by its serial and time; the set fails if any unit does.
#include <atomic>
#include <optional>
#include <string>
#include <vector>

#include "app/common/check_run.h"
#include "core/session/source_set.h"

namespace ydscope::cli {

struct CheckSetPlan {
  CheckPlan check;                 // for every unit, with each unit's session its spec's config
  std::vector<SourceSpec> lidars;  // two or more, in --port order (source_specs_from)
  std::optional<std::string> reports_folder;
  bool json = false;  // stdout: one JSON object for the set instead of the text
};

// Exit status: 130 when Ctrl-C cut the run short; 1 when a unit could not be tested, its link
// failed mid-run or its report could not be written; 3 when a unit failed a criterion; 0 when every
// unit passed. A UsageError for one unit (a scan rate its model cannot do) is thrown once all are done.
int run_check_set(const CheckSetPlan& plan, const std::atomic<bool>& stop);

}  // namespace ydscope::cli
