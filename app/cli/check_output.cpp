#include "app/cli/check_output.h"

#include <algorithm>
#include <string>

#include "app/cli/lap_json.h"
#include "app/cli/session_cli.h"
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

void print_check_json(std::FILE* file, const CheckRecord& record) {
  JsonOut out(file);
  const LapTimingStatistics& t = record.observations.timing;
  out.raw(R"({"type":"check","verdict":)");
  out.string(outcome_word(check_outcome(record)));
  out.raw(R"(,"failed":[)");
  bool first = true;
  for (const CriterionResult& r : record.results) {
    if (r.verdict == Verdict::Pass) continue;
    if (!first) out.raw(",");
    first = false;
    out.string(r.id);
  }
  out.raw(R"(],"interrupted":)");
  out.raw(record.interrupted ? "true" : "false");
  out.raw(R"(,"failure":)");
  if (record.failure.empty())
    out.raw("null");
  else
    out.string(record.failure);
  out.raw(R"(,"seconds":)");
  out.fixed(record.measured_seconds, 3);
  const auto string_or_null = [&out](const char* key, const std::string& text) {
    out.raw(key);
    if (text.empty())
      out.raw("null");
    else
      out.string(text);
  };
  string_or_null(R"(,"operator":)", record.context.operator_name);
  string_or_null(R"(,"station":)", record.context.station);
  string_or_null(R"(,"command_line":)", record.context.command_line);
  out.raw(R"(,"ydscope_version":)");
  out.string(kVersion);
  out.raw(R"(,"device":{)");
  write_device_fields(out, record.started);
  out.raw(R"(},"criteria":[)");
  for (std::size_t i = 0; i < record.results.size(); ++i) {
    const CriterionResult& r = record.results[i];
    out.raw(i ? R"(,{"id":)" : R"({"id":)");
    out.string(r.id);
    out.raw(R"(,"title":)");
    out.string(r.title);
    out.raw(R"(,"verdict":)");
    out.string(r.verdict == Verdict::Pass ? "pass" : "fail");
    out.raw(R"(,"value":)");
    out.fixed_or_null(r.value, 6);
    out.raw(R"(,"measured":)");
    out.string(r.measured);
    out.raw(R"(,"limit":)");
    out.string(r.limit);
    out.raw("}");
  }
  out.raw(R"(],"timing":{"laps":)");
  out.integer(t.laps);
  out.raw(R"(,"normal_laps":)");
  out.integer(t.normal_laps);
  out.raw(R"(,"interruptions":)");
  out.integer(t.interruptions);
  out.raw(R"(,"gaps":[)");
  for (std::size_t i = 0; i < t.gaps.size(); ++i) {
    const TimingGap& gap = t.gaps[i];
    out.raw(i ? R"(,{"from_s":)" : R"({"from_s":)");
    out.fixed(gap.from_s, 3);
    out.raw(R"(,"to_s":)");
    out.fixed(gap.to_s, 3);
    out.raw(R"(,"turns_lost":)");
    out.fixed(gap.turns_lost, 1);
    out.raw(R"(,"cause":)");
    out.string(gap.cause == TimingGap::Cause::Stall ? "stall" : "lost_zero_packet");
    out.raw(R"(,"text":)");
    out.string(describe_timing_gap(gap));
    out.raw("}");
  }
  out.raw("]");
  out.raw(R"(,"mean_hz":)");
  out.fixed(t.mean_hz, 4);
  out.raw(R"(,"jitter_pct":)");
  out.fixed(t.jitter_pct, 3);
  out.raw(R"(,"sample_rate_hz":)");
  out.fixed(t.sample_rate_hz, 1);
  out.raw(R"(,"points":)");
  out.integer(t.points);
  out.raw(R"(,"lost_samples":)");
  out.integer(t.lost_samples);
  out.raw("}");
  out.raw(R"(,"sector":)");
  if (record.sector) {
    const SectorStatistics& s = *record.sector;
    out.raw(R"({"name":)");
    out.string(record.observations.sector_name.value_or(""));
    out.raw(R"(,"points":)");
    out.integer(s.points);
    out.raw(R"(,"valid":)");
    out.integer(s.valid);
    const auto summary = [&out](const char* name, const ValueSummary& v) {
      out.raw(name);
      out.raw(R"({"count":)");
      out.integer(v.count);
      out.raw(R"(,"mean":)");
      out.fixed(v.mean, 2);
      out.raw(R"(,"median":)");
      out.fixed(v.median, 2);
      out.raw(R"(,"stddev":)");
      out.fixed(v.stddev, 2);
      out.raw(R"(,"min":)");
      out.fixed(v.min, 2);
      out.raw(R"(,"max":)");
      out.fixed(v.max, 2);
      out.raw("}");
    };
    summary(R"(,"range_mm":)", s.range_mm);
    summary(R"(,"flat_distance_mm":)", s.flat_distance_mm);
    out.raw("}");
  } else {
    out.raw("null");
  }
  out.raw("}\n");
  out.flush();
}

}  // namespace ydscope::cli
