// ydscope-cli check: an acceptance test of one unit against its model's limits, for the bench, and
// unit after unit with --loop for the production line (check_station.h).
#include <unistd.h>

#include <csignal>
#include <cstdio>
#include <filesystem>
#include <stdexcept>
#include <string>
#include <utility>

#include "app/common/arguments.h"
#include "app/cli/check_output.h"
#include "app/cli/check_set.h"
#include "app/cli/check_station.h"
#include "app/common/check_report.h"
#include "app/common/check_run.h"
#include "app/cli/cli_command.h"
#include "app/cli/session_cli.h"
#include "app/cli/source_options.h"

namespace ydscope::cli {
namespace {

constexpr std::string_view kCheckHelp =
    R"(usage: ydscope-cli check --port PATH [--model auto|M] [--seconds S] [--scan-hz F] [--ranging-khz K]
                         [--sector A:B [--band MIN:MAX] --target-mm D [--tolerance-mm T] [--noise-mm N]]
                         [--format text|json] [--report OUT.html] [--operator NAME] [--station NAME]
                         [limit options]
       ydscope-cli check --port PATH [--name N] --port PATH [--name N] ... [--reports DIR] [...]
       ydscope-cli check --loop --station NAME --operator NAME [--port PATH] [--reports DIR] [...]

Runs an acceptance test of the lidar: reads its identity and health, sets the scan frequency (and
the ranging frequency when asked), lets the motor settle, measures for S seconds, reads the health
again and stops the lidar. Then one line per criterion with the measured value, the limit and
PASS or FAIL:

  identity                the model code matches the model; firmware and serial were read
  health                  no error or warning (A5 91/92 before and after; on G1 also every lap's
                          CT bits)
  scan rate               the measured rate (laps per second over the run) within a tolerance of
                          the target
  scan jitter             the robust std-dev of the samples per lap (each lap's length as the
                          unit's sample clock measures it), in % of their median, below a limit
  sample rate             samples per second against the ranging frequency in use
  link                    checksum errors, resync bytes, G1 CRC8 failures, queue drops, lost samples
  valid returns           the share of points with a return and no interference flag
  blocked sectors         no sector of 4° or more stays without returns (95 % of its samples over
                          the last 3 s) while the rest of the turn sees them; a failure says
                          "blocked 40°–75° for 12 s"
  valid returns in A:B    with --sector A:B: the same share among the sector's points
  range bias              with --target-mm D too: the sector's mean range (along its middle)
                          against D, a flat target square to the sector's middle
  range noise             with --target-mm D too: the std-dev of those ranges

Limits come from the manuals where they give one, otherwise from documented defaults (the table
is in docs/check.md, "Acceptance limits"); every limit has an option below.

options:
  --port PATH            serial port (see `ydscope-cli ports`) or tcp://host:port; once per lidar
                         to check several at once (below)
  --name NAME            with several --port: a name per --port (default lidar0, lidar1, ...)
  --serial S             with several --port: the unit a name belongs to, on whichever port it is
  --model MODEL          auto (default: from the device-info model code), G1, G6, TG15, TG30, TG50
  --baud B               line rate, or auto to probe (see `ydscope-cli info --help`)
  --seconds S            how long to measure (default 10, 1 to 3600)
  --settle-seconds S     laps not judged after setting the frequencies (default 1, 0 to 60)
  --scan-hz F            the scan rate to set and hold the unit to (default: the model's: G1 9,
                         G6 8, TG 10 Hz; within 5 to 12 Hz)
  --ranging-khz K        set this ranging frequency first (G6/TG: 4, 8 or 9; G1's is fixed)
  --sector A:B           also judge the points from A to B degrees (may cross 0, e.g. 350:10)
  --band MIN:MAX         count only returns MIN to MAX mm away in the sector (the target, not
                         the wall behind it); misses still count against it
  --target-mm D          a flat target D mm away fills the sector: judge bias and noise
  --tolerance-mm T       |bias| limit (default 2 % of D, at least 20 mm)
  --noise-mm N           std-dev limit (default 1 % of D, at least 10 mm)
  --format FORMAT        text (default) or json (one object, schema below)
  --report OUT.html      also write a self-contained HTML report (criteria table, scan rate over
                         time, the sector's histogram, the last lap from above) to archive with
                         the unit; written even when the run fails or is interrupted
  --operator NAME        who runs the check, written into the report (and the station log)
  --station NAME         where it runs (a test station's name), written the same way
  --loop                 a test station: check each unit as it is plugged in, until Ctrl-C (below)
  --reports DIR          with --loop: the folder for the reports and the station log (default .);
                         with several --port: the folder for each unit's report
  --distance-scale MM    mm per distance count, overriding the model's (see `decode --help`)
  --conventions C        field (default): read the unit as real units of its model and firmware write
                         (G6 S/2 mm, 18 k samples/s; TG S mm, no correction); manual: as its manual says.
                         docs/conventions.md lists every value and its source

limit options (defaults in brackets):
  --scan-tolerance-pct P         scan rate within P % of the target [2]
  --jitter-pct P                 scan jitter (samples per lap) at most P % [2]
  --sample-rate-tolerance-pct P  samples/s within P % of the ranging frequency [2]
  --max-checksum-errors N        [0]    --max-resync-bytes N   [0]
  --max-crc8-failures N          [0]    --max-queue-drops N    [0]
  --max-lost-samples N           [0]
  --min-valid-pct P              valid returns among all points [50]
  --min-sector-valid-pct P       valid returns in the sector [95]

Several lidars at once (two or more --port): every unit is checked at the same time over one
run, each as above. Each unit's lines are what check prints for it alone, under "NAME (PORT):";
then "lidars: NAME PASS|FAIL|INCOMPLETE (MODEL SERIAL), ..." and "overall: PASS|FAIL|INCOMPLETE".
The set fails when any unit fails, else is incomplete when any was not judged to the end. With
--reports DIR each unit's report is DIR/SERIAL-YYYYMMDD-HHMMSS.html (UTC); --report names one
file and goes with one --port. Exit status: 130 after Ctrl-C, 1 when a unit could not be tested,
its link failed or its report could not be written, 3 when a unit failed, 0 when all passed.
json: {"type":"check_set","verdict","failed":[names],"incomplete":[names],"units":[{"name","port",
  "verdict","report","failure","check":{the one-unit object below, or null when not tested}}]}

A test station (--loop, with --station and --operator): waits for a unit on --port PATH (or,
without --port, on the first lidar port `ydscope-cli ports` would list), checks it as above, writes
its report to DIR/SERIAL-YYYYMMDD-HHMMSS.html (UTC), appends one row to DIR/check-log.csv and
DIR/check-log.jsonl (time, station, operator, port, serial, model, firmware, verdict, failed ids,
scan_hz, jitter_pct, samples_per_s, valid_pct, range_bias_mm, range_noise_mm, lost_samples,
checksum_errors, measured_s, duration_s, note, report; appended and flushed row by row, never
rewritten), says PASS/FAIL on stderr, waits for the unit to be unplugged, then for the next. A
unit that cannot be tested or is cut short is logged as incomplete. Ctrl-C while waiting closes the
station (exit 0); Ctrl-C during a unit's run logs it as incomplete and exits 130.

On a terminal, progress is shown on stderr. Ctrl-C stops the lidar and prints the verdict on what
was measured until then, marked as interrupted. A run cut short (Ctrl-C, or the link failing
mid-run) is never a pass: its verdict is INCOMPLETE in the text, JSON and report alike.

json: {"type":"check","verdict":"pass"|"fail"|"incomplete","failed":[ids],"interrupted":bool,"failure":null|
  sentence,"seconds":S,"operator":null|name,"station":null|name,"command_line":text,
  "ydscope_version":V,"device":{as `info`},"criteria":[{"id","title","verdict","value","measured",
  "limit"}],"timing":{"laps","normal_laps","interruptions","mean_hz","jitter_pct","sample_rate_hz",
  "points","lost_samples"},"sector":null|{"name","points","valid","range_mm":{...},
  "flat_distance_mm":{"count","mean","median","stddev","min","max"}}}
  Criterion ids: identity, health, scan_rate, scan_jitter, sample_rate, link, valid_returns,
  blockage, sector_valid, range_bias, range_noise.

exit status: 0 every criterion passed; 3 at least one failed; 1 the device or the link failed (a
sentence on stderr; when it failed mid-run the verdict on what was measured is still printed);
2 usage error (a port that does not exist included); 130 interrupted by Ctrl-C (the verdict
printed covers only the time measured).

examples:
  ydscope-cli check --port /dev/ttyUSB0
  ydscope-cli check --port /dev/ttyUSB0 --model G6 --seconds 30 --scan-hz 10 --ranging-khz 8
  ydscope-cli check --port /dev/ttyUSB0 --sector 350:10 --target-mm 2000 --format json | jq .verdict
  ydscope-cli check --port /dev/ttyUSB0 --report "check-$(date +%F-%H%M%S).html"
  ydscope-cli check --port /dev/ttyUSB0 --name front --port /dev/ttyUSB1 --name rear --reports ~/qa
  ydscope-cli check --loop --station bench-2 --operator ana --port /dev/ydlidar --reports ~/qa
)";

struct LimitOption {
  const char* name;
  double AcceptanceLimits::*field;
  double max;
  double scale;  // option value -> limit (percent to share for the valid-return limits)
};

constexpr LimitOption kLimitOptions[] = {
    {"scan-tolerance-pct", &AcceptanceLimits::scan_hz_tolerance_pct, 100, 1},
    {"jitter-pct", &AcceptanceLimits::scan_jitter_max_pct, 100, 1},
    {"sample-rate-tolerance-pct", &AcceptanceLimits::sample_rate_tolerance_pct, 100, 1},
    {"max-checksum-errors", &AcceptanceLimits::max_checksum_errors, 1e12, 1},
    {"max-resync-bytes", &AcceptanceLimits::max_resync_bytes, 1e12, 1},
    {"max-crc8-failures", &AcceptanceLimits::max_crc8_failures, 1e12, 1},
    {"max-queue-drops", &AcceptanceLimits::max_queue_drops, 1e12, 1},
    {"max-lost-samples", &AcceptanceLimits::max_lost_samples, 1e12, 1},
    {"min-valid-pct", &AcceptanceLimits::min_valid_share, 100, 0.01},
    {"min-sector-valid-pct", &AcceptanceLimits::min_sector_valid_share, 100, 0.01},
};

// The command as typed, quoted for a POSIX shell where it needs it, for the report.
std::string command_line(std::span<const std::string> raw) {
  std::string line = "ydscope-cli check";
  for (const std::string& arg : raw) {
    const bool plain = !arg.empty() && arg.find_first_not_of(
                                           "abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ"
                                           "0123456789-_./:=,+@%") == std::string::npos;
    if (plain) {
      line += " " + arg;
      continue;
    }
    line += " '";
    for (const char c : arg) line += c == '\'' ? std::string("'\\''") : std::string(1, c);
    line += "'";
  }
  return line;
}

void show_on_terminal(const std::string& line) {
  std::fprintf(stderr, "\r\033[K%s", line.c_str());
  std::fflush(stderr);
}

CheckPlan plan_from(const Arguments& args, SessionConfig session) {
  CheckPlan plan;
  plan.session = std::move(session);
  plan.distance_scale = args.number("distance-scale", kMinDistanceScale, kMaxDistanceScale);
  plan.seconds = args.number("seconds", 1, 3600).value_or(10);
  plan.settle_seconds = args.number("settle-seconds", 0, 60).value_or(1);
  plan.scan_hz = args.number("scan-hz", 0.1, 100);
  if (const auto khz = args.integer("ranging-khz", 1, 100)) plan.ranging_khz = static_cast<std::uint16_t>(*khz);
  if (const auto text = args.value("sector")) {
    std::string error;
    plan.sector = parse_sector(*text, error);
    if (!plan.sector) throw UsageError("--sector: " + error);
  }
  if (const auto band = args.value("band")) {
    if (!plan.sector) throw UsageError("--band needs --sector A:B (the angles the band narrows)");
    std::string error;
    if (!set_range_band(*plan.sector, *band, error)) throw UsageError("--band: " + error);
  }
  plan.target_mm = args.number("target-mm", 1, 1e6);
  plan.bias_tolerance_mm = args.number("tolerance-mm", 0, 1e6);
  plan.noise_max_mm = args.number("noise-mm", 0, 1e6);
  if (plan.target_mm && !plan.sector) throw UsageError("--target-mm needs --sector A:B (the angles the target fills)");
  if ((plan.bias_tolerance_mm || plan.noise_max_mm) && !plan.target_mm)
    throw UsageError("--tolerance-mm and --noise-mm need --target-mm D (the target's distance)");
  for (const LimitOption& option : kLimitOptions)
    if (const auto value = args.number(option.name, 0, option.max))
      plan.limit_overrides.emplace_back(option.field, *value * option.scale);
  plan.context.operator_name = args.value("operator").value_or("");
  plan.context.station = args.value("station").value_or("");
  if (isatty(STDERR_FILENO) == 1) plan.progress = show_on_terminal;
  plan.warning = [](const std::string& text) { std::fprintf(stderr, "ydscope-cli: warning: %s\n", text.c_str()); };
  return plan;
}

// --loop: a station names itself and whoever runs it, and keeps its files in a folder it can write.
StationPlan station_plan_from(const Arguments& args, CheckPlan check) {
  if (args.has("report")) throw UsageError("--report names one file; with --loop give --reports DIR instead");
  for (const char* name : {"station", "operator"})
    if (!args.value(name) || args.value(name)->empty())
      throw UsageError(std::string("--loop needs --") + name + " NAME, written into every report and log row");
  StationPlan plan;
  plan.check = std::move(check);
  plan.port = args.value("port").value_or("");
  plan.reports_folder = args.value("reports").value_or(".");
  plan.json = args.value("format").value_or("text") == "json";
  if (plan.port.rfind("tcp://", 0) == 0)
    throw UsageError("--loop waits for a unit's serial port to appear; give a serial --port, not " + plan.port);
  if (const std::string problem = reports_folder_problem(plan.reports_folder); !problem.empty())
    throw UsageError(problem);
  return plan;
}

// Several lidars at once: each unit's report goes into --reports DIR, named by its serial and time.
CheckSetPlan set_plan_from(const Arguments& args, CheckPlan check, std::vector<SourceSpec> lidars) {
  if (args.has("report"))
    throw UsageError(
        "--report names one file; with several --port give --reports DIR, where each unit's report is "
        "named by its serial and time");
  CheckSetPlan plan;
  plan.check = std::move(check);
  plan.lidars = std::move(lidars);
  plan.reports_folder = args.value("reports");
  plan.json = args.value("format").value_or("text") == "json";
  if (plan.reports_folder)
    if (const std::string problem = reports_folder_problem(*plan.reports_folder); !problem.empty())
      throw UsageError(problem);
  return plan;
}

int run_check_command(std::span<const std::string> raw) {
  std::set<std::string> options{"seconds",   "settle-seconds", "scan-hz",  "ranging-khz", "sector",         "band",
                                "target-mm", "tolerance-mm",   "noise-mm", "format",      "distance-scale", "report",
                                "operator",  "station",        "reports",  "name",        "serial"};
  for (const LimitOption& option : kLimitOptions) options.insert(option.name);
  const Arguments args(raw, session_value_options(options), {"loop"}, 0, source_repeatable_options());
  const std::string format = args.value("format").value_or("text");
  if (format != "text" && format != "json") throw UsageError("--format must be text or json, not '" + format + "'");
  const bool loop = args.has("loop");
  const bool several = args.values("port").size() > 1;
  if (!loop && !several && args.has("reports"))
    throw UsageError("--reports DIR goes with --loop; for one unit give --report OUT.html");
  if (loop) {
    if (several) throw UsageError("--loop checks one unit at a time; give one --port (or none: the first to appear)");
    for (const std::string& option : source_repeatable_options())
      if (args.values(option).size() > 1) throw UsageError("option --" + option + " is given twice");
    for (const char* name : {"name", "serial"})
      if (args.has(name))
        throw UsageError(std::string("--") + name + " names one of several lidars checked at once; not with --loop");
    CheckPlan plan = plan_from(args, session_config_awaiting(args, args.value("port").value_or("")));
    plan.context.command_line = command_line(raw);
    const StationPlan station = station_plan_from(args, std::move(plan));
    end_on_signals();
    return run_check_station(station, end_requested());
  }
  // One lidar is a set of one: its port is read and checked as record and serve read theirs.
  std::vector<SourceSpec> lidars = source_specs_from(args, /*scan=*/true);
  CheckPlan plan = plan_from(args, lidars.front().config);
  plan.context.command_line = command_line(raw);
  if (several) {
    const CheckSetPlan set = set_plan_from(args, std::move(plan), std::move(lidars));
    end_on_signals();
    return run_check_set(set, end_requested());
  }
  const std::optional<std::string> report = args.value("report");
  if (report)
    if (const std::string problem = report_output_problem(*report); !problem.empty()) throw UsageError(problem);

  end_on_signals();
  const CheckRecord record = run_check(plan, end_requested());
  if (plan.progress) std::fprintf(stderr, "\r\033[K");
  if (format == "json")
    print_check_json(stdout, record);
  else
    print_check_text(stdout, record);
  std::fflush(stdout);
  if (report) {
    try {
      write_check_report(*report, record);
    } catch (const std::exception& e) {
      std::fprintf(stderr, "ydscope-cli check: %s\n", e.what());
      return kExitFailure;
    }
  }
  if (!record.failure.empty()) {
    std::fprintf(stderr, "ydscope-cli check: %s\n", record.failure.c_str());
    return kExitFailure;
  }
  if (record.interrupted) {
    std::fprintf(stderr, "ydscope-cli check: interrupted after %.1f of %.1f s; the verdict covers only that\n",
                 record.measured_seconds, plan.seconds);
    return kExitInterrupted;
  }
  return all_passed(record.results) ? kExitOk : kExitLidarFault;
}

const RegisterCliCommand check_command{
    {"check", "acceptance test of a lidar against its model's limits (PASS/FAIL per criterion)", kCheckHelp,
     &run_check_command}};

}  // namespace
}  // namespace ydscope::cli
