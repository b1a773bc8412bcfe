#pragma once
// The measuring half of `ydscope-cli check` and of the app's "Run check": connect, set the scan
// (and ranging) frequency, let the motor settle, then gather laps for the run's length into the
// core/analysis accumulators, read the health again, and stop the lidar. What comes out is a
// CheckRecord: the observations, the verdicts, and what the text, JSON and HTML outputs show.
#include <atomic>
#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "core/analysis/acceptance.h"
#include "core/analysis/sector.h"
#include "core/session/session.h"

namespace ydscope {

// Who ran the check, where and how: written into the report and the station log as given.
struct CheckContext {
  std::string command_line;   // the command as typed, or the app's equivalent of it
  std::string operator_name;  // --operator, empty when not given
  std::string station;        // --station, empty when not given
};

struct CheckPlan {
  SessionConfig session;
  std::optional<double> distance_scale;
  std::optional<double> scan_hz;             // empty: the model's default
  std::optional<std::uint16_t> ranging_khz;  // empty: whatever the unit uses
  double seconds = 10;
  double settle_seconds = 1;
  std::optional<Sector> sector;
  std::optional<double> target_mm;
  // Applied to the model's default limits once the model is known (it may be detected).
  std::vector<std::pair<double AcceptanceLimits::*, double>> limit_overrides;
  std::optional<double> bias_tolerance_mm;
  std::optional<double> noise_max_mm;
  CheckContext context;
  // Where the run says what it is doing ("measuring: 2.0 of 10.0 s, ..."), one line at a time,
  // and the connection's warnings. Empty: silent. Called on the thread running run_check.
  std::function<void(const std::string&)> progress;
  std::function<void(const std::string&)> warning;
  // Once the unit has answered (its model, firmware and serial are in the snapshot).
  std::function<void(const SessionSnapshot&)> connected;
};

struct CheckRecord {
  CheckContext context;
  SessionSnapshot started;          // the device as it answered at connect time
  std::int64_t started_unix_s = 0;  // wall clock at connect, for the report's date
  AcceptanceLimits limits;
  CheckObservations observations;
  std::vector<CriterionResult> results;
  std::optional<Sector> sector_region;     // what --sector asked for
  std::optional<SectorStatistics> sector;  // what fell in it
  Lap last_lap;                            // the polar snapshot of the report
  double measured_seconds = 0;
  bool interrupted = false;  // Ctrl-C: the results cover only what was measured until then
  std::string failure;       // the device failed mid-run: one sentence (results are partial)
};

// A run cut short (Ctrl-C, or the link failed mid-run) is neither a pass nor a fail: its criteria
// cover only part of the time asked for. Every format says the same word.
enum class CheckOutcome : std::uint8_t { Pass, Fail, Incomplete };
CheckOutcome check_outcome(const CheckRecord& record);
const char* outcome_word(CheckOutcome outcome);  // "pass", "fail", "incomplete"
// Why a run is incomplete, for people: "interrupted after 2.0 s", "the link failed after 2.0 s: ...".
std::string incomplete_reason(const CheckRecord& record);

// Throws UsageError for a request the detected model cannot do (a scan rate out of its span, a
// ranging frequency it lacks) and std::runtime_error when the device fails before measuring.
// `stop` (set by a signal handler) ends the measurement early.
CheckRecord run_check(const CheckPlan& plan, const std::atomic<bool>& stop);

}  // namespace ydscope
