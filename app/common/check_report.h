#pragma once
// The archive copy of a `ydscope-cli check` run: one self-contained HTML file (inline CSS and SVG,
// no scripts, nothing fetched) with the unit's identity, the criteria table and the pictures an
// engineer looks at first: the scan rate over the run, the sector's histogram and valid share per
// angle, and the last lap from above.
#include <cstdint>
#include <string>

#include "app/common/check_run.h"

namespace ydscope {

std::string check_report_html(const CheckRecord& record);

// A time in UTC as strftime writes it with `format` ("%Y-%m-%dT%H:%M:%SZ"): the report's date,
// its file name and the station log's rows all say the run's start the same way.
std::string utc_text(std::int64_t unix_s, const char* format);

// The report's name in a folder of many: the unit's serial and the run's start (UTC), such as
// "0471655879731342-20261203-201500.html" (a serial's characters other than letters, digits, '-'
// and '_' become '_'; "no-serial" when none was read). A name already taken gets "-2", "-3"...
std::string check_report_path(const std::string& folder, const CheckRecord& record);

// Empty when `path` can take the report, else one sentence saying why not. Asked before the run
// so a mistyped folder does not cost the measurement.
std::string report_output_problem(const std::string& path);

// Empty when `folder` can take reports named by check_report_path (--reports DIR), else one
// sentence saying why not; asked before the run as report_output_problem is.
std::string reports_folder_problem(const std::string& folder);

// Writes beside `path` and renames, so a reader never sees half a report. Throws
// std::runtime_error with a sentence when that fails.
void write_check_report(const std::string& path, const CheckRecord& record);

}  // namespace ydscope
