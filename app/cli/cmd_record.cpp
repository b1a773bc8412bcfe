// ydscope-cli record: every byte between a live lidar and us, both directions, into a .ydrec file,
// an MCAP file, or both.
#include <unistd.h>

#include <atomic>
#include <chrono>
#include <csignal>
#include <cstdio>
#include <filesystem>
#include <functional>
#include <future>
#include <stdexcept>
#include <string>
#include <thread>

#include "app/common/arguments.h"
#include "app/cli/cli_command.h"
#include "app/cli/health_watch.h"
#include "app/cli/link_loss_notes.h"
#include "app/cli/line_quality.h"
#include "app/cli/mcap_output.h"
#include "app/cli/recording_input.h"
#include "app/cli/record_sources.h"
#include "app/cli/source_options.h"
#include "app/cli/session_cli.h"
#include "core/bridge/live_topics.h"
#include "core/protocol/scan_decoder.h"
#include "core/record/recording_reader.h"
#include "core/record/recording_writer.h"

namespace ydscope::cli {
namespace {

constexpr std::string_view kHelpText =
    R"(usage: ydscope-cli record --port PATH (--out FILE | --mcap OUT.mcap | both) [--model auto|MODEL]
                          [--baud B|auto] [--seconds S] [--force] [MCAP options]
       ydscope-cli record --port PATH [--name NAME] [--pose X,Y,YAW[,flip]] --port PATH ...
                          (--out FILE | --mcap OUT.mcap | both) [--model ...] [--baud ...] [--seconds S]

Connects to the lidar, starts it scanning and records every byte in both directions (the start-up
commands and replies, then the scan stream) with its time, and the device's details, into FILE
(format: core/record/recording_format.h; replay it with `ydscope-cli replay FILE` or decode it
with `ydscope-cli decode FILE`). The file is written as it grows: if the program is killed, the
file is still readable up to the last ~100 ms.

With --mcap, the same session goes live into an MCAP file as well (or instead): /scan, /points,
/diagnostics and the link bytes, as `ydscope-cli export --help` describes. Its chunks are closed
and flushed at least once a second, so a killed recorder leaves an MCAP whose flushed chunks a
streaming reader recovers (it lacks the summary; `ydscope-cli export` of the .ydrec makes a full one).

Several lidars: give --port once for each; all go into one FILE (recording format version 2),
every lap tagged with its lidar's name by replay and decode; --mcap puts each lidar's topics under
its name (/NAME/scan, /NAME/points ...) with every pose on /tf_static, as `export` does. Each
lidar has a session of its own and reconnects by itself: one that stops is said in one line on
stderr and the others keep recording. --seconds counts from when every lidar scans (or was said
to be in trouble).

options:
  --port PATH      serial port (see `ydscope-cli ports`) or tcp://host:port; repeat for several lidars
  --name NAME      several lidars: each one's name (letters, digits, _), once per --port in the
                   same order (default lidar0, lidar1, ...)
  --pose X,Y,YAW[,flip]  several lidars: where each sits on the robot, once per --port, as
                   ROS says it (REP-103): metres forward, metres left, degrees counter-clockwise;
                   flip when mounted upside down (default 0,0,0)
  --out FILE       the recording to write (.ydrec by convention): a regular file in a folder
                   that exists (not a device such as /dev/null: a recording is read back); an
                   existing file is refused unless --force is given
  --mcap OUT.mcap  the MCAP file to write live; an existing file is refused unless --force
  --model MODEL    auto (default: detect from the device info), G1, G6, TG15, TG30, TG50; with
                   several --port, once for all or once per --port
  --baud B         line rate, or auto to probe (default: the model's, 230400 when auto); like --model
  --conventions C  field (default): read the unit as real units of its model and firmware write
                   (G6 S/2 mm, 18 k samples/s; TG S mm, no correction); manual: as its manual says.
                   docs/conventions.md lists every value and its source
  --seconds S      stop after S seconds of scanning (default: until Ctrl-C)
  --force          overwrite FILE and OUT.mcap
  --no-reconnect   end the recording at the first link fault; by default a lidar that drops
                   (a pulled cable, a stall) is reconnected, its settings put back, and the
                   gap marked in the files (link_fault metadata, /diagnostics), said on stderr
)" YDSCOPE_MCAP_OPTIONS_HELP R"(
On a terminal, progress (time, bytes, laps) is shown on stderr and updated in place. Ctrl-C ends
the recording cleanly: the file is closed, the lidar stopped and the summary printed.

output: one summary line on stdout per file (several lidars: a line for the file, then one per
lidar: "  NAME: MODEL on PORT, B bytes from the device, H bytes to it, L laps"), read back from the finished .ydrec (L: laps decoded
from it) and counted while writing the MCAP:
  recorded FILE: S s, B bytes from the device, H bytes to it, L laps
  wrote OUT.mcap: L laps, M messages in C chunks, B bytes
When the lidar reported a health warning or error, the first line ends with the worst of them:
  ...; the lidar reported a health error: error (error code 0x00FF) (A5 91)

health: a warning or an error the lidar reports (its A5 91/92 answer, or G1's CT health bits) is
one line on stderr when it first shows and again whenever it changes, back to ok included.
A bad line (more than one packet in twenty, and at least ten, failing the checksum) is one line
on stderr at the end: check the cable, the power supply and that no other program has the port.

exit status: 0 recorded (a health warning does not change this); 3 recorded, but the lidar
reported a health error; 1 the device or the file failed (one sentence on stderr; what was
recorded until then stays in FILE; several lidars: one of them never scanned); 2 usage error
(a bad --pose or --name, a port that does not exist).

examples:
  ydscope-cli record --port /dev/ttyUSB0 --out bench.ydrec --seconds 10
  ydscope-cli record --port tcp://192.168.1.20:2000 --model G6 --out g6.ydrec
  ydscope-cli record --port /dev/ttyUSB0 --mcap bench.mcap --seconds 60
  ydscope-cli record --port /dev/ttyUSB0 --out bench.ydrec --mcap bench.mcap
  ydscope-cli record --port /dev/ttyUSB0 --name front --pose 0.2,0,0 \
                     --port /dev/ttyUSB1 --name back --pose -0.2,0,180,flip --out robot.ydrec --mcap robot.mcap
)";

std::atomic<bool> interrupted{false};
extern "C" void record_on_signal(int) { interrupted.store(true); }  // C linkage: a unique name

using Clock = std::chrono::steady_clock;

double seconds_since(Clock::time_point start) { return std::chrono::duration<double>(Clock::now() - start).count(); }

// Waits for a posted command's result, still noticing Ctrl-C.
CommandResult await(std::future<CommandResult>& result) {
  while (result.wait_for(std::chrono::milliseconds(100)) != std::future_status::ready) {
  }
  return result.get();
}

void show_progress(const std::string& out, double seconds, const CounterSnapshot& c, double rate) {
  std::fprintf(stderr, "\r\033[Krecording %s: %.1f s, %llu bytes from the device (%.1f kB/s), %llu laps", out.c_str(),
               seconds, static_cast<unsigned long long>(c.bytes_received), rate / 1000.0,
               static_cast<unsigned long long>(c.laps));
  if (c.checksum_errors)
    std::fprintf(stderr, ", %llu checksum errors", static_cast<unsigned long long>(c.checksum_errors));
  std::fflush(stderr);
}

// ", N laps" decoded from the finished file (what a replay will give), or "" without a model.
std::string laps_in(const std::string& path, const RecordingMetadata& metadata) {
  const ModelProfile* profile = metadata.model ? find_profile(*metadata.model) : nullptr;
  if (!profile) return "";
  ScanDecoder decoder(*profile, metadata.distance_scale);
  read_recording_device_bytes(path, [&](std::span<const std::uint8_t> chunk, std::int64_t t_ns) {
    decoder.feed(chunk, t_ns, [](const Lap&) {});
  });
  decoder.finish([](const Lap&) {});
  return ", " + std::to_string(decoder.counters().laps) + " laps";
}

// Waits for a posted command's result.
CommandResult run_and_wait(const std::function<void(CommandCallback)>& post) {
  std::promise<CommandResult> promise;
  auto result = promise.get_future();
  post([&promise](const CommandResult& r) { promise.set_value(r); });
  return await(result);
}

int run_record(std::span<const std::string> raw) {
  const Arguments args(raw, with_mcap_value_options(session_value_options({"out", "seconds", "mcap", "name", "pose"})),
                       with_mcap_flags({"force", "no-reconnect"}), 0, source_repeatable_options());
  if (args.values("port").size() > 1) {
    if (const auto out = args.value("out")) refuse_to_overwrite(*out, args, "--out");
    end_on_signals(record_on_signal);
    return record_sources(args, interrupted);
  }
  for (const std::string& option : source_repeatable_options())
    if (args.values(option).size() > 1) throw UsageError("option --" + option + " is given twice");
  if (args.value("name") || args.value("pose"))
    throw UsageError("--name and --pose place one of several lidars; give them with two or more --port");
  const auto out_option = args.value("out");
  const auto mcap_option = args.value("mcap");
  if (!out_option && !mcap_option) throw UsageError("say where to record: --out FILE.ydrec, --mcap FILE.mcap, or both");
  if (out_option && mcap_option && *out_option == *mcap_option)
    throw UsageError("--out and --mcap must be different files");
  const std::string out = out_option.value_or("");
  const auto seconds = args.number("seconds", 0.001, 1e7);
  // Before connecting: /dev/null once recorded for a second and then failed as "not a recording".
  if (out_option)
    if (const std::string problem = recording_output_problem(out); !problem.empty()) throw UsageError(problem);
  if (out_option) refuse_to_overwrite(out, args, "--out");
  if (mcap_option) refuse_to_overwrite(*mcap_option, args, "--mcap");
  McapExportOptions mcap_options = mcap_options_from(args);
  SessionConfig config = session_config_from(args, /*scan=*/true);
  // An unattended recording outlives a USB glitch: the session reconnects, the file marks the gap.
  config.reconnect = !args.has("no-reconnect");
  mcap_options.ros.model = config.model;
  const bool tty = ::isatty(STDERR_FILENO) == 1;
  LinkLossNotes notes("ydscope-cli record", config.address, "recording on; the gap is marked in the file");

  Session session(4);
  end_on_signals(record_on_signal);
  // The MCAP side is written from the session's tap on a thread of its own.
  std::unique_ptr<LiveTopics> live;
  if (mcap_option) {
    LiveTopicsOptions options;
    options.topics = mcap_options;
    options.mcap_path = *mcap_option;
    options.attach = false;  // tapped right after the connect intent, below
    std::string error;
    live = LiveTopics::start(session, std::move(options), error);
    if (!live) throw std::runtime_error(error);
  }
  // Recording starts right after the connect intent, so the start-up exchange is in the files
  // too: creating the MCAP file first would give the I/O thread time to send the first command.
  session.connect(config);
  if (live) live->attach_source(0);
  if (out_option) {
    const CommandResult start =
        run_and_wait([&](CommandCallback done) { session.start_recording(out, std::move(done)); });
    if (!start.ok) throw std::runtime_error(start.message);
  }
  const std::string shown = out_option ? out : *mcap_option;
  // Between session checks; a failed MCAP write ends the recording like a failed .ydrec.
  const auto idle = [&](std::chrono::milliseconds wait) {
    std::this_thread::sleep_for(wait);
    if (live)
      if (const std::string failed = live->error(); !failed.empty()) throw std::runtime_error(failed);
  };

  std::string failure;
  HealthWatch health("ydscope-cli record");
  health.clear_line_first(tty);
  const auto connect_start = Clock::now();
  Lap lap;
  SessionSnapshot s = session.snapshot();
  while (!interrupted.load()) {  // until scanning; a first connect that fails ends the run at once
    s = session.snapshot();
    if (s.state == LinkState::Scanning || s.state == LinkState::Failed) break;
    if (s.state == LinkState::Reconnecting) {
      failure = s.message;
      break;
    }
    if (seconds_since(connect_start) > 60) {
      failure = "gave up after 60 s waiting for " + config.address + " (" + describe_snapshot(s) + ")";
      break;
    }
    idle(std::chrono::milliseconds(50));
  }
  if (s.state == LinkState::Failed) failure = s.message;
  if (failure.empty()) notes.follow(s, tty);

  const auto scan_start = Clock::now();
  const std::uint64_t bytes_at_scan_start = s.counters.bytes_received;
  auto last_progress = Clock::time_point{};
  while (failure.empty() && !interrupted.load() && (!seconds || seconds_since(scan_start) < *seconds)) {
    // Nobody looks at laps here beyond the newest one's CT health; keep the queue from filling.
    if (session.laps().drain_newest(lap) > 0) health.observe_lap(lap);
    s = session.snapshot();
    health.observe_answer(s.health);
    if (out_option && !s.recording) {
      failure = s.message.empty() ? "recording stopped" : s.message;
      break;
    }
    notes.follow(s, tty);
    if (s.state == LinkState::Failed || (!config.reconnect && !scanning(s.state))) {
      failure = s.message.empty() ? "the scan stopped (" + describe_snapshot(s) + ")" : s.message;
      break;
    }
    if (tty && Clock::now() - last_progress >= std::chrono::milliseconds(250)) {
      const double elapsed = seconds_since(scan_start);
      const double rate =
          elapsed > 0.2 ? static_cast<double>(s.counters.bytes_received - bytes_at_scan_start) / elapsed : 0.0;
      show_progress(shown, elapsed, s.counters, rate);
      last_progress = Clock::now();
    }
    idle(std::chrono::milliseconds(50));
  }
  if (tty) std::fputs("\r\033[K", stderr);

  // Close the files first (flushed and complete), then stop the lidar. The .ydrec's close is asked
  // for before the MCAP's taps close, without waiting between, so both end at the same byte.
  std::promise<void> file_closed;
  std::future<void> file_closing = file_closed.get_future();
  if (out_option)
    session.stop_recording([&file_closed](const CommandResult&) { file_closed.set_value(); });
  else
    file_closed.set_value();
  const bool live_written = !live || live->stop();
  file_closing.wait();
  if (!live_written) throw std::runtime_error(live->error());
  session.disconnect();
  const SessionSnapshot end = session.wait_until(
      [](const SessionSnapshot& x) { return x.state == LinkState::Idle || x.state == LinkState::Failed; },
      std::chrono::seconds(3));
  std::fputs(checksum_warning("ydscope-cli record", end.counters.packets, end.counters.checksum_errors).c_str(),
             stderr);

  if (out_option) {
    std::string error;
    const auto summary = summarize_recording(out, error);
    if (!summary) throw std::runtime_error(error);
    if (!failure.empty() && summary->device_bytes == 0 && summary->host_bytes == 0) {
      std::filesystem::remove(out);  // the port never opened: an empty recording helps nobody
      if (live) std::filesystem::remove(live->mcap_path());
      throw std::runtime_error(failure);
    }
    std::printf("recorded %s: %.1f s, %llu bytes from the device, %llu bytes to it%s%s\n", out.c_str(),
                static_cast<double>(summary->duration_ns) / 1e9, static_cast<unsigned long long>(summary->device_bytes),
                static_cast<unsigned long long>(summary->host_bytes), laps_in(out, summary->metadata).c_str(),
                health.summary_note().c_str());
    print_recording_warnings("ydscope-cli record", summary->damage);
  } else if (!failure.empty() && s.counters.bytes_received == 0 && s.counters.bytes_sent == 0) {
    std::filesystem::remove(live->mcap_path());
    throw std::runtime_error(failure);
  }
  if (live) {
    std::printf("%s%s\n", live->file_summary().c_str(), out_option ? "" : health.summary_note().c_str());
    if (live->dropped())
      std::fprintf(stderr, "ydscope-cli record: warning: %s lacks %llu records: writing it fell behind the lidar\n",
                   live->mcap_path().c_str(), static_cast<unsigned long long>(live->dropped()));
  }
  std::fflush(stdout);
  if (!failure.empty()) throw std::runtime_error(failure + "; what was recorded until then is in " + shown);
  return health.worst() == HealthLevel::Error ? kExitLidarFault : kExitOk;
}

const RegisterCliCommand registration{
    {"record", "record every byte of a live lidar session to a file", kHelpText, &run_record}};

}  // namespace
}  // namespace ydscope::cli
