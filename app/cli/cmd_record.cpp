// ydscope-cli record: every byte between a live lidar and us, both directions, into a .ydrec file.
#include <unistd.h>

#include <atomic>
#include <chrono>
#include <csignal>
#include <cstdio>
#include <filesystem>
#include <future>
#include <stdexcept>
#include <string>
#include <thread>

#include "app/common/arguments.h"
#include "app/cli/cli_command.h"
#include "app/cli/recording_input.h"
#include "app/cli/session_cli.h"
#include "core/protocol/scan_decoder.h"
#include "core/record/recording_reader.h"
#include "core/record/recording_writer.h"

namespace ydscope::cli {
namespace {

constexpr std::string_view kHelpText = R"(usage: ydscope-cli record --port PATH --out FILE [--model auto|MODEL] [--baud B|auto]
                          [--seconds S] [--force]

Connects to the lidar, starts it scanning and records every byte in both directions (the start-up
commands and replies, then the scan stream) with its time, and the device's details, into FILE
(format: core/record/recording_format.h; replay it with `ydscope-cli replay FILE` or decode it
with `ydscope-cli decode FILE`). The file is written as it grows: if the program is killed, the
file is still readable up to the last ~100 ms.

options:
  --port PATH      serial port (see `ydscope-cli ports`) or tcp://host:port
  --out FILE       the recording to write (.ydrec by convention): a regular file in a folder
                   that exists (not a device such as /dev/null: a recording is read back); an
                   existing file is refused unless --force is given
  --model MODEL    auto (default: detect from the device info), G1, G6, TG15, TG30, TG50
  --baud B         line rate, or auto to probe (default: the model's, 230400 when auto)
  --seconds S      stop after S seconds of scanning (default: until Ctrl-C)
  --force          overwrite FILE

On a terminal, progress (time, bytes, laps) is shown on stderr and updated in place. Ctrl-C ends
the recording cleanly: the file is closed, the lidar stopped and the summary printed.

output: one summary line on stdout, read back from the finished file (L: laps decoded from it):
  recorded FILE: S s, B bytes from the device, H bytes to it, L laps

exit status: 0 recorded; 1 the device or the file failed (one sentence on stderr; what was
recorded until then stays in FILE); 2 usage error.

examples:
  ydscope-cli record --port /dev/ttyUSB0 --out bench.ydrec --seconds 10
  ydscope-cli record --port tcp://192.168.1.20:2000 --model G6 --out g6.ydrec
)";

std::atomic<bool> interrupted{false};
extern "C" void record_on_signal(int) { interrupted.store(true); }  // C linkage: a unique name

using Clock = std::chrono::steady_clock;

double seconds_since(Clock::time_point start) {
  return std::chrono::duration<double>(Clock::now() - start).count();
}

// Waits for a posted command's result, still noticing Ctrl-C.
CommandResult await(std::future<CommandResult>& result) {
  while (result.wait_for(std::chrono::milliseconds(100)) != std::future_status::ready) {
  }
  return result.get();
}

// rate: bytes per second since scanning started (the session's own rate updates once a second).
void show_progress(const std::string& out, double seconds, const CounterSnapshot& c, double rate) {
  std::fprintf(stderr, "\r\033[Krecording %s: %.1f s, %llu bytes from the device (%.1f kB/s), %llu laps", out.c_str(),
               seconds, static_cast<unsigned long long>(c.bytes_received), rate / 1000.0,
               static_cast<unsigned long long>(c.laps));
  if (c.checksum_errors) std::fprintf(stderr, ", %llu checksum errors", static_cast<unsigned long long>(c.checksum_errors));
  std::fflush(stderr);
}

// ", N laps" decoded from the finished file (what a replay will give), or "" without a model.
std::string laps_in(const std::string& path, const RecordingMetadata& metadata) {
  const ModelProfile* profile = metadata.model ? find_profile(*metadata.model) : nullptr;
  if (!profile) return "";
  ScanDecoder decoder(*profile, metadata.distance_scale);
  read_recording_device_bytes(path, [&](std::span<const std::uint8_t> chunk) { decoder.feed(chunk, 0, [](const Lap&) {}); });
  decoder.finish([](const Lap&) {});
  return ", " + std::to_string(decoder.counters().laps) + " laps";
}

int run_record(std::span<const std::string> raw) {
  const Arguments args(raw, session_value_options({"out", "seconds"}), {"force"});
  const std::string out = args.required("out");
  const auto seconds = args.number("seconds", 0.001, 1e7);
  // Before connecting: /dev/null once recorded for a second and then failed as "not a recording".
  if (const std::string problem = recording_output_problem(out); !problem.empty()) throw UsageError(problem);
  if (!args.has("force") && std::filesystem::exists(out))
    throw UsageError(out + " already exists; choose another --out or add --force to overwrite it");
  const SessionConfig config = session_config_from(args, /*scan=*/true);
  const bool tty = ::isatty(STDERR_FILENO) == 1;

  Session session(4);
  std::signal(SIGINT, record_on_signal);
  std::signal(SIGTERM, record_on_signal);
  // Recording starts right after the connect intent, so the start-up exchange is in the file too.
  session.connect(config);
  std::promise<CommandResult> started_promise;
  auto started = started_promise.get_future();
  session.start_recording(out, [&started_promise](const CommandResult& r) { started_promise.set_value(r); });
  const CommandResult start = await(started);
  if (!start.ok) throw std::runtime_error(start.message);

  std::string failure;
  const auto connect_start = Clock::now();
  Lap lap;
  SessionSnapshot s = session.snapshot();
  while (!interrupted.load()) {  // until scanning (or failed)
    s = session.wait_until(
        [](const SessionSnapshot& x) { return x.state == LinkState::Scanning || x.state == LinkState::Failed; },
        std::chrono::milliseconds(200));
    if (s.state == LinkState::Scanning || s.state == LinkState::Failed) break;
    if (seconds_since(connect_start) > 60) {
      failure = "gave up after 60 s waiting for " + config.address + " (" + describe_snapshot(s) + ")";
      break;
    }
  }
  if (s.state == LinkState::Failed) failure = s.message;

  const auto scan_start = Clock::now();
  const std::uint64_t bytes_at_scan_start = s.counters.bytes_received;
  auto last_progress = Clock::time_point{};
  while (failure.empty() && !interrupted.load() && (!seconds || seconds_since(scan_start) < *seconds)) {
    session.laps().drain_newest(lap);  // nobody looks at laps here; keep the queue from filling
    s = session.snapshot();
    if (!s.recording) {
      failure = s.message.empty() ? "recording stopped" : s.message;
      break;
    }
    if (s.state != LinkState::Scanning && s.state != LinkState::CommandInProgress) {
      failure = s.message.empty() ? "the scan stopped (" + describe_snapshot(s) + ")" : s.message;
      break;
    }
    if (tty && Clock::now() - last_progress >= std::chrono::milliseconds(250)) {
      const double elapsed = seconds_since(scan_start);
      const double rate = elapsed > 0.2 ? static_cast<double>(s.counters.bytes_received - bytes_at_scan_start) / elapsed : 0.0;
      show_progress(out, elapsed, s.counters, rate);
      last_progress = Clock::now();
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(50));
  }
  if (tty) std::fputs("\r\033[K", stderr);

  // Close the file first (flushed and complete), then stop the lidar.
  std::promise<CommandResult> stopped_promise;
  auto stopped = stopped_promise.get_future();
  session.stop_recording([&stopped_promise](const CommandResult& r) { stopped_promise.set_value(r); });
  await(stopped);
  session.disconnect();
  session.wait_until([](const SessionSnapshot& x) { return x.state == LinkState::Idle || x.state == LinkState::Failed; },
                     std::chrono::seconds(3));

  std::string error;
  const auto summary = summarize_recording(out, error);
  if (!summary) throw std::runtime_error(error);
  if (!failure.empty() && summary->device_bytes == 0 && summary->host_bytes == 0) {
    std::filesystem::remove(out);  // the port never opened: an empty recording helps nobody
    throw std::runtime_error(failure);
  }
  std::printf("recorded %s: %.1f s, %llu bytes from the device, %llu bytes to it%s\n", out.c_str(),
              static_cast<double>(summary->duration_ns) / 1e9, static_cast<unsigned long long>(summary->device_bytes),
              static_cast<unsigned long long>(summary->host_bytes), laps_in(out, summary->metadata).c_str());
  std::fflush(stdout);
  if (!summary->warning.empty() || !summary->error.empty())
    std::fprintf(stderr, "ydscope-cli record: warning: %s\n", (summary->error.empty() ? summary->warning : summary->error).c_str());
  if (!failure.empty()) throw std::runtime_error(failure + "; what was recorded until then is in " + out);
  return kExitOk;
}

const RegisterCliCommand registration{
    {"record", "record every byte of a live lidar session to a file", kHelpText, &run_record}};

}  // namespace
}  // namespace ydscope::cli
