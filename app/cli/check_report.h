#pragma once
// The archive copy of a `ydscope-cli check` run: one self-contained HTML file (inline CSS and SVG,
// no scripts, nothing fetched) with the unit's identity, the criteria table and the pictures an
// engineer looks at first: the scan rate over the run, the sector's histogram and valid share per
// angle, and the last lap from above.
#include <string>

#include "app/cli/check_run.h"

namespace ydscope::cli {

std::string check_report_html(const CheckRecord& record);

// Empty when `path` can take the report, else one sentence saying why not. Asked before the run
// so a mistyped folder does not cost the measurement.
std::string report_output_problem(const std::string& path);

// Writes beside `path` and renames, so a reader never sees half a report. Throws
// std::runtime_error with a sentence when that fails.
void write_check_report(const std::string& path, const CheckRecord& record);

}  // namespace ydscope::cli
