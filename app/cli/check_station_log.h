#pragma once
// The station log of `ydscope-cli check --loop`: one row per unit tested, in CSV (for a
// spreadsheet) and JSON lines (for scripts), both appended and flushed row by row, never
// rewritten, so a crash or a pulled power cord loses at most the unit under test.
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "app/common/check_run.h"

namespace ydscope::cli {

struct StationLogRow {
  std::int64_t unix_s = 0;  // when the unit's test started
  std::string station;
  std::string operator_name;
  std::string port;
  std::string serial;  // empty: the unit never answered
  std::string model;
  std::string firmware;
  std::string verdict;              // pass, fail or incomplete (check_outcome's words)
  std::vector<std::string> failed;  // criterion ids
  std::optional<double> scan_hz, scan_jitter_pct, sample_rate_per_s, valid_returns_pct, range_bias_mm, range_noise_mm;
  std::optional<std::uint64_t> lost_samples, checksum_errors;
  double measured_s = 0;  // the part judged
  double duration_s = 0;  // plugged in and found to verdict written
  std::string note;       // why the run is incomplete, or empty
  std::string report;     // the HTML report's path, or empty
};

// The row of a run that produced a record; `note` is filled in when it is incomplete.
StationLogRow station_log_row(const CheckRecord& record);

class StationLog {
 public:
  // `folder` holds check-log.csv and check-log.jsonl (created when missing).
  explicit StationLog(std::string folder);
  // Appends the row to both files and flushes them; throws std::runtime_error with a sentence
  // when a file cannot be written.
  void append(const StationLogRow& row) const;
  std::string csv_path() const;
  std::string jsonl_path() const;

 private:
  std::string folder_;
};

// The CSV header and one row as CSV and JSON text (each without the newline).
std::string station_log_csv_header();
std::string station_log_csv(const StationLogRow& row);
std::string station_log_json(const StationLogRow& row);

}  // namespace ydscope::cli
