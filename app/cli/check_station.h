#pragma once
// `ydscope-cli check --loop`: a test station. Each unit plugged in is checked as `check` checks
// one, its report written to the reports folder under its serial and time, and one row appended
// to the station log; then the station waits for it to be pulled out and for the next, until
// Ctrl-C. What a person at the station needs to know goes to stderr as whole lines.
#include <atomic>
#include <string>

#include "app/common/check_run.h"

namespace ydscope::cli {

struct StationPlan {
  CheckPlan check;             // for every unit; session.address becomes the port each is found on
  std::string port;            // the port to wait on; empty: the first lidar port that appears
  std::string reports_folder;  // the reports and check-log.csv / check-log.jsonl
  bool json = false;           // stdout: one JSON object per unit instead of the text verdict
};

// Exit status: 0 when stopped while waiting for a unit, 130 when Ctrl-C cut a unit's run short
// (logged as incomplete), 1 when the station log could not be written.
int run_check_station(StationPlan plan, const std::atomic<bool>& stop);

}  // namespace ydscope::cli
