#include "app/cli/check_output.h"

#include <algorithm>
#include <cctype>
#include <string>
#include <utility>

#include "app/cli/lap_json.h"
#include "app/cli/session_cli.h"
#include "core/text/json_writer.h"
#include "core/version.h"

namespace ydscope::cli {

namespace {

const char* verdict_word(Verdict v) { return v == Verdict::Pass ? "PASS" : "FAIL"; }

std::string failed_ids(const CheckRecord& record) {
  std::string ids;
  for (const CriterionResult& r : record.results)
    if (r.verdict == Verdict::Fail) ids += (ids.empty() ? "" : ", ") + r.id;
  return ids;
}

}  // namespace

void print_check_text(std::FILE* out, const CheckRecord& record) {
  const SessionSnapshot& s = record.started;
  const ModelProfile* profile = record.observations.profile;
  std::fprintf(out, "check of %s on %s, serial %s: %.1f s measured, %llu laps%s\n",
               profile ? std::string(profile->name).c_str() : "?", s.link.c_str(),
               s.device ? s.device->serial.c_str() : "?", record.measured_seconds,
               static_cast<unsigned long long>(record.observations.timing.laps),
               record.interrupted ? " (interrupted)" : "");
  if (const UnitConventions* c = record.observations.conventions)
    std::fprintf(out, "read with the %s conventions: %s\n", std::string(c->id).c_str(), std::string(c->label).c_str());
  std::size_t width = 0;
  for (const CriterionResult& r : record.results) width = std::max(width, r.title.size());
  for (const CriterionResult& r : record.results)
    std::fprintf(out, "%s  %-*s  %s  [limit: %s]\n", verdict_word(r.verdict), static_cast<int>(width), r.title.c_str(),
                 r.measured.c_str(), r.limit.c_str());
  const std::size_t failed = static_cast<std::size_t>(std::count_if(
      record.results.begin(), record.results.end(), [](const auto& r) { return r.verdict == Verdict::Fail; }));
  const std::vector<TimingGap>& gaps = record.observations.timing.gaps;
  if (!gaps.empty()) {
    std::fprintf(out, "interruptions: %zu, left out of the per-lap figures\n", gaps.size());
    for (const TimingGap& gap : gaps) std::fprintf(out, "  %s\n", describe_timing_gap(gap).c_str());
  }
  const CheckOutcome outcome = check_outcome(record);
  if (outcome == CheckOutcome::Incomplete)
    std::fprintf(out, "verdict: INCOMPLETE (%s; of what was measured, %zu of %zu criteria failed%s%s)\n",
                 incomplete_reason(record).c_str(), failed, record.results.size(), failed ? ": " : "",
                 failed_ids(record).c_str());
  else if (failed == 0)
    std::fprintf(out, "verdict: PASS (%zu criteria)\n", record.results.size());
  else
    std::fprintf(out, "verdict: FAIL (%zu of %zu criteria: %s)\n", failed, record.results.size(),
                 failed_ids(record).c_str());
}

namespace {

void write_criteria(JsonObject& check, const std::vector<CriterionResult>& results) {
  JsonArray criteria = check.array("criteria");
  for (const CriterionResult& r : results)
    criteria.object()
        .field("id", r.id)
        .field("title", r.title)
        .field("verdict", r.verdict == Verdict::Pass ? "pass" : "fail")
        .field("value", r.value, 6)
        .field("measured", r.measured)
        .field("limit", r.limit);
}

void write_timing(JsonObject& check, const LapTimingStatistics& t) {
  JsonObject timing = check.object("timing");
  timing.field("laps", t.laps).field("normal_laps", t.normal_laps).field("interruptions", t.interruptions);
  {
    JsonArray gaps = timing.array("gaps");
    for (const TimingGap& gap : t.gaps)
      gaps.object()
          .field("from_s", gap.from_s, 3)
          .field("to_s", gap.to_s, 3)
          .field("turns_lost", gap.turns_lost, 1)
          .field("cause", gap.cause == TimingGap::Cause::Stall ? "stall" : "lost_zero_packet")
          .field("text", describe_timing_gap(gap));
  }
  timing.field("mean_hz", t.mean_hz, 4).field("jitter_pct", t.jitter_pct, 3);
  timing.field("sample_rate_hz", t.sample_rate_hz, 1).field("points", t.points).field("lost_samples", t.lost_samples);
}

void write_value_summary(JsonObject& sector, std::string_view key, const ValueSummary& v) {
  sector.object(key)
      .field("count", v.count)
      .field("mean", v.mean, 2)
      .field("median", v.median, 2)
      .field("stddev", v.stddev, 2)
      .field("min", v.min, 2)
      .field("max", v.max, 2);
}

void write_sector(JsonObject& check, const CheckRecord& record) {
  if (!record.sector) {
    check.field("sector", nullptr);
    return;
  }
  const SectorStatistics& s = *record.sector;
  JsonObject sector = check.object("sector");
  sector.field("name", record.observations.sector_name.value_or(""));
  sector.field("points", s.points).field("valid", s.valid);
  write_value_summary(sector, "range_mm", s.range_mm);
  write_value_summary(sector, "flat_distance_mm", s.flat_distance_mm);
}

// The members of check's JSON object, written into `check` (alone, or as one unit of a set).
void write_check_fields(JsonObject& check, const CheckRecord& record) {
  check.field("type", "check").field("verdict", outcome_word(check_outcome(record)));
  {
    JsonArray failed = check.array("failed");
    for (const CriterionResult& r : record.results)
      if (r.verdict != Verdict::Pass) failed.item(r.id);
  }
  check.field("interrupted", record.interrupted).field("failure", text_or_null(record.failure));
  check.field("seconds", record.measured_seconds, 3);
  check.field("operator", text_or_null(record.context.operator_name));
  check.field("station", text_or_null(record.context.station));
  check.field("command_line", text_or_null(record.context.command_line));
  check.field("ydscope_version", kVersion);
  {
    JsonObject device = check.object("device");
    write_device_fields(device, record.started);
  }
  write_criteria(check, record.results);
  write_timing(check, record.observations.timing);
  write_sector(check, record);
}

}  // namespace

void print_check_json(std::FILE* file, const CheckRecord& record) {
  JsonOut out(file);
  {
    JsonObject check(out.buffer());
    write_check_fields(check, record);
  }
  out.raw("\n");
  out.flush();
}

std::string unit_name(const CheckRecord& record) {
  const CheckObservations& o = record.observations;
  const std::string model = o.profile ? std::string(o.profile->name) : std::string("lidar");
  return record.started.device ? model + " " + record.started.device->serial : model;
}

CheckOutcome set_outcome(const std::vector<UnitCheck>& units) {
  const auto any = [&units](CheckOutcome outcome) {
    return std::any_of(units.begin(), units.end(),
                       [outcome](const UnitCheck& u) { return check_outcome(u.record) == outcome; });
  };
  return any(CheckOutcome::Fail)         ? CheckOutcome::Fail
         : any(CheckOutcome::Incomplete) ? CheckOutcome::Incomplete
                                         : CheckOutcome::Pass;
}

namespace {

std::string upper(std::string word) {
  for (char& c : word) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
  return word;
}

// "lidar1, lidar2": the units whose verdict is `outcome`.
std::string names_with(const std::vector<UnitCheck>& units, CheckOutcome outcome) {
  std::string names;
  for (const UnitCheck& u : units)
    if (check_outcome(u.record) == outcome) names += (names.empty() ? "" : ", ") + u.name;
  return names;
}

}  // namespace

void print_check_set_text(std::FILE* out, const std::vector<UnitCheck>& units) {
  for (const UnitCheck& u : units) {
    std::fprintf(out, "%s (%s):\n", u.name.c_str(), u.port.c_str());
    if (u.tested)
      print_check_text(out, u.record);
    else
      std::fprintf(out, "verdict: INCOMPLETE (not tested: %s)\n", u.record.failure.c_str());
    if (!u.report.empty()) std::fprintf(out, "report: %s\n", u.report.c_str());
    std::fprintf(out, "\n");
  }
  std::string each;
  for (const UnitCheck& u : units)
    each += (each.empty() ? "" : ", ") + u.name + " " + upper(outcome_word(check_outcome(u.record))) +
            (u.record.started.device ? " (" + unit_name(u.record) + ")" : "");
  std::fprintf(out, "lidars: %s\n", each.c_str());
  const CheckOutcome outcome = set_outcome(units);
  const std::string failed = names_with(units, CheckOutcome::Fail);
  const std::string incomplete = names_with(units, CheckOutcome::Incomplete);
  std::fprintf(out, "overall: %s (%zu lidars%s%s%s%s)\n", upper(outcome_word(outcome)).c_str(), units.size(),
               failed.empty() ? "" : "; failed: ", failed.c_str(),
               incomplete.empty() ? "" : "; not judged: ", incomplete.c_str());
}

void print_check_set_json(std::FILE* file, const std::vector<UnitCheck>& units) {
  JsonOut out(file);
  {
    JsonObject set(out.buffer());
    set.field("type", "check_set").field("verdict", outcome_word(set_outcome(units)));
    for (const auto& [key, outcome] :
         {std::pair{"failed", CheckOutcome::Fail}, {"incomplete", CheckOutcome::Incomplete}}) {
      JsonArray names = set.array(key);
      for (const UnitCheck& u : units)
        if (check_outcome(u.record) == outcome) names.item(u.name);
    }
    JsonArray each = set.array("units");
    for (const UnitCheck& u : units) {
      JsonObject unit = each.object();
      unit.field("name", u.name).field("port", u.port).field("verdict", outcome_word(check_outcome(u.record)));
      unit.field("report", text_or_null(u.report)).field("failure", text_or_null(u.record.failure));
      if (!u.tested) {
        unit.field("check", nullptr);
        continue;
      }
      JsonObject check = unit.object("check");
      write_check_fields(check, u.record);
    }
  }
  out.raw("\n");
  out.flush();
}

}  // namespace ydscope::cli
