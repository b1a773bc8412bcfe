#include "app/cli/check_station.h"

#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <stdexcept>

#include "app/cli/check_output.h"
#include "app/cli/check_station_log.h"
#include "app/cli/cli_command.h"
#include "app/cli/port_wait.h"
#include "app/common/check_report.h"
#include "core/analysis/text_format.h"

namespace ydscope::cli {

namespace {

// A whole line on stderr, clearing a progress line a terminal may be showing.
void say(const std::string& line) {
  std::fprintf(stderr, "%s%s\n", isatty(STDERR_FILENO) == 1 ? "\r\033[K" : "", line.c_str());
  std::fflush(stderr);
}

std::string verdict_line(const CheckRecord& record, const std::string& report) {
  const CheckOutcome outcome = check_outcome(record);
  std::string failed;
  for (const CriterionResult& r : record.results)
    if (r.verdict == Verdict::Fail) failed += (failed.empty() ? "" : ", ") + r.title;
  std::string line;
  switch (outcome) {
    case CheckOutcome::Pass: line = "PASS — " + unit_name(record) + "; unplug it"; break;
    case CheckOutcome::Fail:
      line = "FAIL — " + unit_name(record) + " (" + failed + "); unplug it and set it aside";
      break;
    case CheckOutcome::Incomplete:
      line = "INCOMPLETE — " + unit_name(record) + " (" + incomplete_reason(record) + "); not judged, test it again";
      break;
  }
  return line + (report.empty() ? "" : "\n  report: " + report);
}

struct Tally {
  unsigned pass = 0, fail = 0, incomplete = 0;
  void add(const std::string& verdict) { (verdict == "pass" ? pass : verdict == "fail" ? fail : incomplete) += 1; }
};

}  // namespace

int run_check_station(StationPlan plan, const std::atomic<bool>& stop) {
  const StationLog log(plan.reports_folder);
  const std::string where = plan.port.empty() ? "the first lidar port to appear" : plan.port;
  say(format_text("station %s, operator %s: reports and the log (%s) go to %s", plan.check.context.station.c_str(),
                  plan.check.context.operator_name.c_str(), "check-log.csv, .jsonl", plan.reports_folder.c_str()));
  Tally tally;
  int status = kExitOk;
  while (!stop.load()) {
    say("waiting for a unit on " + where + " ... (Ctrl-C closes the station)");
    const std::optional<std::string> port = wait_for_unit(plan.port, stop);
    if (!port) break;
    plan.check.session.address = *port;
    const std::optional<PortNode> unit = port_node(*port);
    plan.check.connected = [&port](const SessionSnapshot& s) {
      const std::string model = s.device && s.device->profile ? std::string(s.device->profile->name) : "lidar";
      say("testing " + model + " " + (s.device ? s.device->serial : std::string("(no serial)")) + " on " + *port +
          " ...");
    };
    const auto found = std::chrono::steady_clock::now();
    StationLogRow row;
    std::string report;
    try {
      const CheckRecord record = run_check(plan.check, stop);
      if (plan.json)
        print_check_json(stdout, record);
      else
        print_check_text(stdout, record);
      std::fflush(stdout);
      report = check_report_path(plan.reports_folder, record);
      try {
        write_check_report(report, record);
      } catch (const std::exception& e) {
        say(std::string("the report was not written: ") + e.what());
        report.clear();
      }
      row = station_log_row(record);
      say(verdict_line(record, report));
      if (record.interrupted) status = kExitInterrupted;
    } catch (const std::exception& e) {  // the unit failed before anything was measured
      row.unix_s =
          std::chrono::duration_cast<std::chrono::seconds>(std::chrono::system_clock::now().time_since_epoch()).count();
      row.station = plan.check.context.station;
      row.operator_name = plan.check.context.operator_name;
      row.verdict = outcome_word(CheckOutcome::Incomplete);
      row.note = e.what();
      say("INCOMPLETE — the unit on " + *port + " was not tested: " + e.what() + "; unplug it");
      if (stop.load()) status = kExitInterrupted;
    }
    row.port = *port;  // as waited on (the snapshot's link text adds the baud)
    row.report = report;
    row.duration_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - found).count();
    try {
      log.append(row);
    } catch (const std::exception& e) {
      say(std::string("ydscope-cli check: ") + e.what() + "; the station stops so no unit goes unlogged");
      return kExitFailure;
    }
    tally.add(row.verdict);
    if (status == kExitInterrupted) break;
    if (!wait_until_unplugged(*port, unit, stop)) break;
  }
  say(format_text("station closed: %u passed, %u failed, %u incomplete; log: %s", tally.pass, tally.fail,
                  tally.incomplete, log.csv_path().c_str()));
  return status;
}

}  // namespace ydscope::cli
