// ydscope-cli replay: a recording's device bytes, played back through the replay link with their
// original timing (or faster), decoded into laps as `decode` prints them.
#include <chrono>
#include <csignal>
#include <cstdio>
#include <functional>
#include <stdexcept>
#include <string>
#include <vector>

#include <boost/asio/error.hpp>
#include <boost/asio/io_context.hpp>
#include <boost/asio/signal_set.hpp>

#include "app/cli/session_cli.h"
#include "app/common/arguments.h"
#include "app/cli/cli_command.h"
#include "app/cli/lap_json.h"
#include "app/cli/lap_output.h"
#include "app/cli/recording_input.h"
#include "app/cli/source_playback.h"
#include "core/link/replay_link.h"
#include "core/protocol/scan_decoder.h"

namespace ydscope::cli {
namespace {

constexpr std::string_view kReplayHelp =
    R"(usage: ydscope-cli replay FILE [--speed X] [--format jsonl|csv|summary] [--model MODEL]
                          [--distance-scale X] [--keep-gaps]

Plays back the bytes the lidar sent in a recording made by `ydscope-cli record` (or the app),
with their original timing, and decodes them into laps exactly as `ydscope-cli decode` does.

  FILE                 a .ydrec recording
  --speed X            1 (default) as recorded, 2 twice as fast, 0.5 half speed, 0 as fast as
                       possible; otherwise from 0.001 to 1000000
  --format FORMAT      jsonl (default): one JSON object per lap, then the summary line; csv: one
                       row per point; summary: only the summary line (schemas: `ydscope-cli
                       decode --help`). A lap's t is its recorded time, so every speed prints
                       the same lines, and the same as decode of FILE.
  --model MODEL        decode as this model instead of the one the recording names
  --distance-scale X   mm per raw distance unit, instead of the one used while recording
  --conventions C      field or manual, instead of the conventions the recording was made with
                       (recordings without them were read as the manuals say)
  --keep-gaps          wait out a gap in the recording as recorded. By default a gap of more than
                       5 s without a byte from the lidar (an outage the recorder waited out) is
                       skipped; either way stderr says where it is and how long it lasts:
                       "the recording has a gap of 59.0 s at 12.3 s without a byte from the
                       lidar; skipped to 71.3 s"

Ctrl-C stops early; the summary of what was played is still printed. A recording cut off by a
killed recorder plays up to its last complete record, with a warning on stderr. A record time
that goes back, or jumps more than 60 s ahead, is damage: that record plays at once (the later
ones keep their spacing), with a warning.

exit status: 0 played to the end (or stopped by Ctrl-C); 1 the file cannot be read; 2 usage error
(including a recording of a version or header this ydscope cannot read).

examples:
  ydscope-cli replay bench.ydrec --speed 0 --format summary
  ydscope-cli replay g6.ydrec --speed 4 > laps.jsonl
)";

constexpr std::size_t kReadBuffer = 4096;

int run_replay(std::span<const std::string> raw) {
  const Arguments args(raw, {"speed", "format", "model", "distance-scale", "conventions"}, {"keep-gaps"},
                       /*max_positionals=*/1);
  const std::string path = args.single_positional("FILE (a .ydrec recording)");
  require_existing_file(path, "recording");
  const double speed = args.number("speed", 0, kMaxReplaySpeed).value_or(1.0);
  if (speed > 0 && speed < kMinReplaySpeed)  // slower would wait for days between two records
    throw UsageError("--speed must be 0 (as fast as possible) or from 0.001 to 1000000, not '" + *args.value("speed") +
                     "'");
  const LapFormat format = parse_lap_format(args.value("format"), LapFormat::Jsonl);

  const auto scale_option = args.number("distance-scale", kMinDistanceScale, kMaxDistanceScale);
  const RecordingPlan plan =
      recording_plan_or_throw(path, RecordingUse::Replay, args.value("model"), scale_option, reading_option(args));
  print_recording_warnings("ydscope-cli replay", plan.warnings());
  if (plan.several_sources()) {
    end_on_signals();
    print_source_laps(path, plan, format, {speed, args.has("keep-gaps")}, {}, end_requested());
    return kExitOk;
  }
  const ModelProfile& profile = *plan.profile;
  const auto scale = plan.distance_scale;

  boost::asio::io_context io;
  std::string error;
  ReplayOptions options{.speed = speed, .skip_gaps = !args.has("keep-gaps")};
  options.on_gap = [](const RecordingGap& gap, bool skipped) { print_gap("ydscope-cli replay", gap, skipped); };
  auto link = ReplayLink::open(io, path, options, error);
  if (!link) throw std::runtime_error(error);  // the file changed since the plan read it

  ScanDecoder decoder(profile, *plan.conventions, scale);
  JsonOut out(stdout);
  LapPrinter printer(out, format, profile.ct_carries_info);
  const auto on_lap = [&](const Lap& lap) {
    printer.print(lap);
    out.flush();  // a program reading the pipe gets each lap as it is played
  };

  boost::asio::signal_set signals(io, SIGINT, SIGTERM, SIGHUP);  // as end_on_signals
  signals.async_wait([&](const boost::system::error_code& ec, int) {
    if (!ec) link->close();
  });
  std::vector<std::uint8_t> buffer(kReadBuffer);
  bool played_to_end = false;  // not stopped by Ctrl-C: a missing lap is then news
  std::function<void()> read_next = [&] {
    link->async_read_some(buffer, [&](const boost::system::error_code& ec, std::size_t n) {
      // Stamped with the recorded time, not the playback's: t is the same at any speed.
      if (n > 0) decoder.feed({buffer.data(), n}, link->recorded_time_of_last_read(), on_lap);
      if (ec) {
        played_to_end = ec == boost::asio::error::eof;
        signals.cancel();
        return;  // end of the recording, or Ctrl-C
      }
      read_next();
    });
  };
  read_next();
  io.run();

  decoder.finish(on_lap);
  if (printer.wants_summary()) write_summary(out, decoder.counters(), plan.summary.metadata.start_wall_time);
  out.flush();
  if (played_to_end) say_why_no_lap("ydscope-cli replay", profile.name, decoder.counters());
  return kExitOk;
}

const RegisterCliCommand replay_command{
    {"replay", "play a recording back with its timing and decode it into laps", kReplayHelp, &run_replay}};

}  // namespace
}  // namespace ydscope::cli
