#include "app/cli/check_station_log.h"

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <stdexcept>

#include "app/common/check_report.h"
#include "core/text/json_string.h"
#include "core/text/number_text.h"

namespace ydscope::cli {

namespace {

// One list of columns, so the CSV header, the CSV rows and the JSON keys cannot drift apart.
constexpr const char* kColumns[] = {
    "time",           "station",      "operator",        "port",       "serial",        "model",     "firmware",
    "verdict",        "failed",       "scan_hz",         "jitter_pct", "samples_per_s", "valid_pct", "range_bias_mm",
    "range_noise_mm", "lost_samples", "checksum_errors", "measured_s", "duration_s",    "note",      "report"};
constexpr std::size_t kColumnCount = sizeof kColumns / sizeof kColumns[0];

std::string number(const std::optional<double>& value, int decimals) {
  std::string text;
  if (value) append_fixed(text, *value, decimals);
  return text;
}

std::string count(const std::optional<std::uint64_t>& value) {
  std::string text;
  if (value) append_integer(text, *value);
  return text;
}

// Each column's value as text, and whether JSON writes it as a string (else a number or null).
struct Cell {
  std::string text;
  bool is_string = true;
};

std::vector<Cell> cells(const StationLogRow& r) {
  std::string failed;
  for (const std::string& id : r.failed) failed += (failed.empty() ? "" : " ") + id;
  return {{utc_text(r.unix_s, "%Y-%m-%dT%H:%M:%SZ")},
          {r.station},
          {r.operator_name},
          {r.port},
          {r.serial},
          {r.model},
          {r.firmware},
          {r.verdict},
          {failed},
          {number(r.scan_hz, 4), false},
          {number(r.scan_jitter_pct, 3), false},
          {number(r.sample_rate_per_s, 1), false},
          {number(r.valid_returns_pct, 2), false},
          {number(r.range_bias_mm, 1), false},
          {number(r.range_noise_mm, 1), false},
          {count(r.lost_samples), false},
          {count(r.checksum_errors), false},
          {number(r.measured_s, 1), false},
          {number(r.duration_s, 1), false},
          {r.note},
          {r.report}};
}

// RFC 4180: a field holding a comma, a quote or a line break is quoted, its quotes doubled.
std::string csv_field(const std::string& text) {
  if (text.find_first_of(",\"\r\n") == std::string::npos) return text;
  std::string out = "\"";
  for (const char c : text) out += c == '"' ? std::string("\"\"") : std::string(1, c);
  return out + "\"";
}

void append_line(const std::string& path, const std::string& header, const std::string& line) {
  std::FILE* file = std::fopen(path.c_str(), "a");
  if (!file) throw std::runtime_error("could not open the station log " + path + ": " + std::strerror(errno));
  std::string text;
  if (!header.empty() && std::ftell(file) == 0) text = header + "\n";
  text += line + "\n";
  bool ok = std::fwrite(text.data(), 1, text.size(), file) == text.size() && std::fflush(file) == 0;
  const int error = errno;
  if (std::fclose(file) != 0) ok = false;
  if (!ok)
    throw std::runtime_error("could not write to the station log " + path + ": " + std::strerror(error ? error : EIO));
}

}  // namespace

StationLogRow station_log_row(const CheckRecord& record) {
  StationLogRow row;
  row.unix_s = record.started_unix_s;
  row.station = record.context.station;
  row.operator_name = record.context.operator_name;
  row.port = record.started.link;
  const CheckObservations& o = record.observations;
  if (o.profile) row.model = std::string(o.profile->name);
  if (record.started.device) {
    row.serial = record.started.device->serial;
    row.firmware = o.identity.firmware;
  }
  const CheckOutcome outcome = check_outcome(record);
  row.verdict = outcome_word(outcome);
  for (const CriterionResult& r : record.results)
    if (r.verdict == Verdict::Fail) row.failed.push_back(r.id);
  if (outcome == CheckOutcome::Incomplete) row.note = incomplete_reason(record);
  if (o.timing.normal_laps > 0) {
    row.scan_hz = o.timing.mean_hz;
    row.scan_jitter_pct = o.timing.jitter_pct;
    row.sample_rate_per_s = o.timing.sample_rate_hz;
  }
  if (o.points > 0) row.valid_returns_pct = 100.0 * static_cast<double>(o.valid_points) / static_cast<double>(o.points);
  if (o.target_mm && record.sector && record.sector->flat_distance_mm.count >= 2) {
    row.range_bias_mm = record.sector->flat_distance_mm.mean - *o.target_mm;
    row.range_noise_mm = record.sector->flat_distance_mm.stddev;
  }
  row.lost_samples = o.link.lost_samples;
  row.checksum_errors = o.link.checksum_errors;
  row.measured_s = record.measured_seconds;
  return row;
}

std::string station_log_csv_header() {
  std::string text;
  for (std::size_t i = 0; i < kColumnCount; ++i) text += (i ? "," : "") + std::string(kColumns[i]);
  return text;
}

std::string station_log_csv(const StationLogRow& row) {
  std::string text;
  const std::vector<Cell> values = cells(row);
  for (std::size_t i = 0; i < values.size(); ++i) text += (i ? "," : "") + csv_field(values[i].text);
  return text;
}

std::string station_log_json(const StationLogRow& row) {
  std::string text = "{";
  const std::vector<Cell> values = cells(row);
  for (std::size_t i = 0; i < values.size(); ++i) {
    if (i) text += ",";
    append_json_string(text, kColumns[i]);
    text += ":";
    if (std::string_view(kColumns[i]) == "failed") {  // a list for scripts, as in check's JSON
      text += "[";
      for (std::size_t k = 0; k < row.failed.size(); ++k) {
        if (k) text += ",";
        append_json_string(text, row.failed[k]);
      }
      text += "]";
    } else if (values[i].is_string) {
      append_json_string(text, values[i].text);
    } else {
      text += values[i].text.empty() ? "null" : values[i].text;
    }
  }
  return text + "}";
}

StationLog::StationLog(std::string folder) : folder_(std::move(folder)) {}

std::string StationLog::csv_path() const { return (std::filesystem::path(folder_) / "check-log.csv").string(); }
std::string StationLog::jsonl_path() const { return (std::filesystem::path(folder_) / "check-log.jsonl").string(); }

void StationLog::append(const StationLogRow& row) const {
  append_line(csv_path(), station_log_csv_header(), station_log_csv(row));
  append_line(jsonl_path(), {}, station_log_json(row));
}

}  // namespace ydscope::cli
