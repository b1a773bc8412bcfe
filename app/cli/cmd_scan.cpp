// ydscope-cli scan: N laps from a live lidar, as decode prints them.
#include <fcntl.h>
#include <unistd.h>

#include <chrono>
#include <csignal>
#include <cstdio>
#include <stdexcept>
#include <string>

#include "app/common/arguments.h"
#include "app/cli/cli_command.h"
#include "app/cli/health_watch.h"
#include "app/cli/link_loss_notes.h"
#include "app/common/lap_bell.h"
#include "app/cli/lap_json.h"
#include "app/cli/lap_output.h"
#include "app/cli/line_quality.h"
#include "app/cli/session_cli.h"
#include "core/session/session_io.h"
#include "core/record/recording_metadata.h"

namespace ydscope::cli {
namespace {

constexpr std::string_view kScanHelp =
    R"(usage: ydscope-cli scan --port PATH [--model auto|MODEL] [--baud B|auto] --laps N [--format jsonl|csv|summary]

Starts the lidar scanning, prints N complete laps and a summary, then stops the lidar.
Ctrl-C stops early (the lidar is stopped and the summary printed).

options:
  --port PATH           serial port or tcp://host:port
  --model MODEL         auto (default), G1, G6, TG15, TG30, TG50
  --baud B              line rate, or auto to probe (see `ydscope-cli info --help`)
  --laps N              laps to print (1 to 1000000)
  --format FORMAT       jsonl (default): one JSON object per lap, then the summary; csv: a header,
                        then one row per point (see `decode --help`); summary: only the summary
  --distance-scale MM   mm per distance count, overriding the model's (see `decode --help`)
  --no-reconnect        end at the first link fault; by default a lidar that drops after it
                        scanned (a pulled cable, a stall) is reconnected, its settings put back,
                        and the loss and return said on stderr; laps go on (their index from 0)
  --conventions C       field (default): read the unit as real units of its model and firmware write
                        (G6 S/2 mm, 18 k samples/s; TG S mm, no correction); manual: as its manual says.
                        docs/conventions.md lists every value and its source

output: the schema of `ydscope-cli decode --help` (lap objects, then one summary object, whose
bytes count everything the lidar sent, replies included), with the health the session knows:
  a lap's "health" is G1's CT health bits of that lap (as decode prints them) and, on G6/TG,
  the status byte of the lidar's A5 91 answer (0 normal, 1 warning, 2 error; null unanswered;
  the bits of A5 92 on a unit that answers only that);
  the summary adds "health":{"level":"ok|warning|error","source":"A5 91|A5 92|CT","summary":S}
  for the worst health seen during the run (S in words, as info prints it), or null.
  A lap's "t" uses this computer's receive times, and the summary's "start" is the wall-clock
  time of the first printed lap's first byte.

health: a warning or an error the lidar reports (its A5 91/92 answer, or G1's CT health bits) is
one line on stderr when it first shows and again whenever it changes, back to ok included.
A bad line (more than one packet in twenty, and at least ten, failing the checksum) is one line
on stderr at the end: check the cable, the power supply and that no other program has the port.

exit status: 0 N laps were printed (a health warning does not change this); 3 N laps were printed
but the lidar reported a health error; 1 the device failed or stopped sending (one sentence on
stderr); 2 usage error (a port that does not exist included).

example:
  ydscope-cli scan --port /dev/ttyUSB0 --laps 10 --format jsonl
)";

int run_scan(std::span<const std::string> raw) {
  const Arguments args(raw, session_value_options({"laps", "format", "distance-scale"}), {"no-reconnect"});
  const auto laps_wanted = args.integer("laps", 1, 1'000'000);
  if (!laps_wanted) throw UsageError("--laps N is required (how many laps to print)");
  const LapFormat format = parse_lap_format(args.value("format"), LapFormat::Jsonl);
  SessionConfig config = session_config_from(args, /*scan=*/true);
  // A lidar back a second after a USB glitch goes on printing; the first connect still fails fast
  // (connect_or_throw).
  config.reconnect = !args.has("no-reconnect");
  config.distance_scale = args.number("distance-scale", kMinDistanceScale, kMaxDistanceScale);

  LapBell bell;
  // A reader that stops reading (a full pipe) must not keep the lidar spinning: the output gives
  // up once Ctrl-C or SIGTERM comes (JsonOut's give_up). The signals also reach this thread, so a
  // write that does block (a terminal held by Ctrl-S) is interrupted.
  std::optional<EndSignalsStayHere> signals_here(std::in_place);
  Session session(64, [&bell] { bell.ring(); });
  signals_here.reset();
  end_on_signals(/*interrupt_writes=*/true);
  // A reader that goes away (`scan ... | head -1`) must not kill us before the lidar is stopped:
  // the write fails instead, and the loop ends as for Ctrl-C.
  std::signal(SIGPIPE, SIG_IGN);
  const SessionSnapshot started = connect_or_throw(session, config);
  LinkLossNotes notes("ydscope-cli scan", config.address, "laps go on once it is back");
  if (config.distance_scale) session.set_distance_scale(config.distance_scale);
  const bool g1_info = started.device && started.device->profile && started.device->profile->ct_carries_info;

  HealthWatch health("ydscope-cli scan");
  health.observe_answer(started.health);
  JsonOut out(stdout, end_requested());
  LapPrinter printer(out, format, g1_info);
  std::optional<std::string> start;  // wall-clock time of the first printed lap's first byte
  Lap lap;
  std::int64_t printed = 0;
  std::string failure;
  bool reader_gone = false;
  bool output_stuck = false;  // a signal broke a write its reader was not taking
  const auto deliver = [&](const Lap& shown) {
    try {
      printer.print(shown, health.lap_health(shown, g1_info));
      out.flush();  // a program reading the pipe gets each lap as it arrives
    } catch (const std::runtime_error&) {
      // A signal that broke a blocked write ends the run as Ctrl-C does; anything else is a
      // reader that went away.
      (end_requested().load() ? output_stuck : reader_gone) = true;
    }
  };
  while (printed < *laps_wanted && !end_requested().load() && !reader_gone) {
    if (session.laps().try_pop(lap)) {
      health.observe_lap(lap);
      if (!start) {
        const auto since_first_byte = std::chrono::nanoseconds(link_clock_ns() - lap.first_rx_ns);
        start = iso8601_utc(std::chrono::system_clock::now() -
                            std::chrono::duration_cast<std::chrono::system_clock::duration>(since_first_byte));
      }
      deliver(lap);
      ++printed;
      continue;
    }
    const SessionSnapshot s = session.snapshot();
    health.observe_answer(s.health);
    notes.follow(s, false);
    if (s.state == LinkState::Failed || (!config.reconnect && !scanning(s.state))) {
      failure = s.message.empty() ? "the scan stopped (" + describe_snapshot(s) + ")" : s.message;
      break;
    }
    bell.wait(std::chrono::milliseconds(200));
  }
  session.disconnect();  // stops the lidar before the summary
  const SessionSnapshot end = session.wait_until(
      [](const SessionSnapshot& s) { return s.state == LinkState::Idle || s.state == LinkState::Failed; },
      std::chrono::seconds(3));
  if (reader_gone) {  // the lidar is stopped; end as a closed pipe ends any program, quietly
    std::signal(SIGPIPE, SIG_DFL);
    std::raise(SIGPIPE);
  }
  if (output_stuck) {
    // The reader still takes nothing: no summary, and nothing left may block the exit either.
    ::fcntl(STDOUT_FILENO, F_SETFL, ::fcntl(STDOUT_FILENO, F_GETFL) | O_NONBLOCK);
    std::fputs("ydscope-cli scan: ended while its reader took no output; the lidar is stopped, the summary dropped\n",
               stderr);
    return kExitOk;
  }
  DecoderCounters summary;
  summary.bytes = end.counters.bytes_received;
  summary.packets = end.counters.packets;
  summary.checksum_errors = end.counters.checksum_errors;
  summary.zero_packets = end.counters.zero_packets;
  summary.laps = end.counters.laps;
  summary.overflow_points = end.counters.cut_points;  // "cut_points", as decode prints it
  if (printer.wants_summary()) {
    {
      JsonObject line(out.buffer());
      write_summary_fields(line, summary, start);
      health.write_summary_field(line);
    }
    out.raw("\n");
  }
  out.flush();
  std::fflush(stdout);
  std::fputs(checksum_warning("ydscope-cli scan", summary.packets, summary.checksum_errors).c_str(), stderr);
  if (!failure.empty()) throw std::runtime_error(failure);
  return health.worst() == HealthLevel::Error ? kExitLidarFault : kExitOk;
}

const RegisterCliCommand scan_command{
    {"scan", "print N laps from a live lidar (JSON lines or a summary)", kScanHelp, &run_scan}};

}  // namespace
}  // namespace ydscope::cli
