#include "app/cli/record_sources.h"

#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

#include "app/cli/cli_command.h"
#include "app/cli/health_watch.h"
#include "app/cli/line_quality.h"
#include "app/cli/link_loss_notes.h"
#include "app/cli/mcap_output.h"
#include "app/cli/recording_input.h"
#include "app/cli/source_options.h"
#include "core/bridge/live_topics.h"
#include "core/session/source_set.h"
#include "core/record/recorded_conventions.h"
#include "core/record/recording_reader.h"
#include "core/record/source_decoders.h"

namespace ydscope::cli {
namespace {

using Clock = std::chrono::steady_clock;

// A lidar gets this long to start scanning (the session reconnects by itself) before the recording
// goes on without it (it keeps trying all along), or gives up when none scans.
constexpr std::chrono::seconds kSettlePatience{60};

// What the command line says of each lidar as it records: its health and its losses.
struct Watch {
  std::string program;  // "ydscope-cli record", or with the lidar's name for one of several
  std::unique_ptr<HealthWatch> health;
  std::unique_ptr<LinkLossNotes> notes;
};

void show_progress(const std::string& out, double seconds, const SourceSet& set) {
  std::string line;
  for (std::size_t id = 0; id < set.size(); ++id) {
    const SessionSnapshot s = set.session(id).snapshot();
    line += ", " + (named_apart(set.infos()) ? set.info(id).name + " " : std::string()) +
            std::to_string(s.counters.laps) + " laps" +
            (scanning(s.state) ? "" : " (" + std::string(link_state_name(s.state)) + ")");
  }
  std::fprintf(stderr, "\r\033[Krecording %s: %.1f s%s", out.c_str(), seconds, line.c_str());
  std::fflush(stderr);
}

// Per source: the laps decoded from the finished file, as a replay will give them.
std::vector<std::uint64_t> laps_per_source(const std::string& path, const RecordingSummary& summary) {
  std::vector<SourcePlan> plans;
  for (std::size_t id = 0; id < summary.sources.size(); ++id) {
    const RecordingMetadata& metadata = summary.sources[id].metadata;
    const ModelProfile* profile = metadata.model ? find_profile(*metadata.model) : nullptr;
    plans.push_back({source_label(metadata, id), profile, metadata.distance_scale,
                     profile ? &recorded_conventions(metadata, *profile, std::nullopt) : nullptr});
  }
  SourceDecoders decoders(plans);
  std::string error;
  auto reader = RecordingReader::open(path, error);
  if (!reader) throw std::runtime_error(error);
  RecordView record;
  while (reader->next(record)) decoders.feed(record, [](std::size_t, const Lap&) {});
  decoders.finish([](std::size_t, const Lap&) {});
  std::vector<std::uint64_t> laps;
  for (std::size_t id = 0; id < decoders.size(); ++id)
    laps.push_back(decoders.decoder(id) ? decoders.decoder(id)->counters().laps : 0);
  return laps;
}

// What the .ydrec holds, as replay will decode it: one line for a lone lidar, else a line for the
// file and one per lidar.
void print_recording_summary(const std::string& out, const SourceSet& set, const std::vector<Watch>& watches,
                             const RecordingSummary& summary) {
  const auto laps = laps_per_source(out, summary);
  const double seconds = static_cast<double>(summary.duration_ns) / 1e9;
  if (!named_apart(set.infos())) {
    std::printf("recorded %s: %.1f s, %llu bytes from the device, %llu bytes to it%s%s\n", out.c_str(), seconds,
                static_cast<unsigned long long>(summary.device_bytes),
                static_cast<unsigned long long>(summary.host_bytes),
                summary.metadata.model ? (", " + std::to_string(laps.at(0)) + " laps").c_str() : "",
                watches[0].health->summary_note().c_str());
  } else {
    std::printf("recorded %s: %.1f s, %zu lidars\n", out.c_str(), seconds, set.size());
    for (std::size_t id = 0; id < set.size(); ++id) {
      const SourceSummary& s = summary.sources.at(id);
      std::printf("  %s: %s on %s, %llu bytes from the device, %llu bytes to it, %llu laps%s\n",
                  set.info(id).name.c_str(), s.metadata.model.value_or("unknown model").c_str(),
                  set.config(id).address.c_str(), static_cast<unsigned long long>(s.device_bytes),
                  static_cast<unsigned long long>(s.host_bytes), static_cast<unsigned long long>(laps[id]),
                  watches[id].health->summary_note().c_str());
    }
  }
  print_recording_warnings("ydscope-cli record", summary.damage);
}

}  // namespace

int record_sources(const Arguments& args, const std::atomic<bool>& interrupted) {
  const auto out = args.value("out");
  const auto mcap_path = args.value("mcap");
  if (!out && !mcap_path) throw UsageError("say where to record: --out FILE.ydrec, --mcap FILE.mcap, or both");
  if (out && mcap_path && *out == *mcap_path) throw UsageError("--out and --mcap must be different files");
  const auto seconds = args.number("seconds", 0.001, 1e7);
  // Before connecting: /dev/null once recorded for a second and then failed as "not a recording".
  if (out)
    if (const std::string problem = recording_output_problem(*out); !problem.empty()) throw UsageError(problem);
  if (out) refuse_to_overwrite(*out, args, "--out");
  if (mcap_path) refuse_to_overwrite(*mcap_path, args, "--mcap");
  std::vector<SourceSpec> specs = source_specs_from(args, /*scan=*/true);
  // An unattended recording outlives a USB glitch: each session reconnects, the file marks the gap.
  const bool reconnect = !args.has("no-reconnect");
  for (SourceSpec& spec : specs) spec.config.reconnect = reconnect;
  SourceSet set(std::move(specs));
  const bool several = named_apart(set.infos());
  const bool tty = ::isatty(STDERR_FILENO) == 1;
  const std::string shown = out.value_or(mcap_path.value_or(""));

  std::vector<Watch> watches;
  for (std::size_t id = 0; id < set.size(); ++id) {
    const std::string program = "ydscope-cli record" + (several ? ": " + set.info(id).name : std::string());
    Watch watch{program, std::make_unique<HealthWatch>(program),
                std::make_unique<LinkLossNotes>(
                    "ydscope-cli record", who(set, id),
                    several ? "the other lidars keep recording" : "recording on; the gap is marked in the file")};
    watch.health->clear_line_first(tty);
    watches.push_back(std::move(watch));
  }
  std::string error;
  // The MCAP file is written from taps of its own, on a thread of its own.
  std::unique_ptr<LiveTopics> live;
  if (mcap_path) {
    std::vector<LiveSource> live_sources;
    for (std::size_t id = 0; id < set.size(); ++id) live_sources.push_back({&set.session(id), set.info(id), nullptr});
    LiveTopicsOptions options;
    options.topics = mcap_options_from(args);
    options.mcap_path = *mcap_path;
    options.attach = false;  // each session's tap before its connect, below
    live = LiveTopics::start(std::move(live_sources), std::move(options), error);
    if (!live) throw std::runtime_error(error);
  }
  // Every tap before the connect intents (each session runs them in order), so the start-up
  // exchange is in the .ydrec and the MCAP file alike: a tap posted after the connect missed the
  // first A5 65 whenever the connect's first write came before it (seen under ASan).
  if (live)
    for (std::size_t id = 0; id < set.size(); ++id) live->attach_source(id);
  std::unique_ptr<SourcesRecording> recording;
  if (out) {
    recording = set.record(*out, error);
    if (!recording) throw std::runtime_error(error);
  }
  set.connect_all();

  const auto start = Clock::now();
  std::optional<Clock::time_point> scan_start;
  auto last_progress = Clock::time_point{};
  Lap lap;
  std::string failure;
  while (!interrupted.load()) {
    // The .ydrec is written on this thread (pump); the MCAP file on its own.
    if (!recording) std::this_thread::sleep_for(std::chrono::milliseconds(50));
    if (recording && !recording->pump(std::chrono::milliseconds(50))) {
      failure = recording->error();
      break;
    }
    if (live && !live->error().empty()) {
      failure = live->error();
      break;
    }
    if (!scan_start) {
      // --seconds counts from when every lidar scans (or is in trouble); with none scanning there
      // is nothing to record: a lone lidar's first connect that fails ends the run at once.
      const SetStart state = set.start_state();
      const bool patience_out = Clock::now() - start > kSettlePatience;
      if (!state.any_scanned && (state.settled || patience_out)) {
        failure = state.settled ? state.failure
                                : "gave up after " + std::to_string(kSettlePatience.count()) + " s waiting for " +
                                      who(set, 0) + " (" + describe_snapshot(set.session(0).snapshot()) + ")";
        break;
      }
      if (state.settled || patience_out) scan_start = Clock::now();
    }
    // A lidar that fails for good leaves the others recording; with --no-reconnect the first
    // fault ends the recording.
    bool all_failed = true;
    std::string stopped;  // why the last lidar that stopped did
    for (std::size_t id = 0; id < set.size(); ++id) {
      // Nobody looks at laps here beyond the newest one's CT health; keep the queue from filling.
      if (set.session(id).laps().drain_newest(lap) > 0) watches[id].health->observe_lap(lap);
      const SessionSnapshot s = set.session(id).snapshot();
      watches[id].health->observe_answer(s.health);
      if (scan_start) watches[id].notes->follow(s, tty);
      const bool stopped_here = s.state == LinkState::Failed || (scan_start && !reconnect && !scanning(s.state));
      if (stopped_here) stopped = s.message.empty() ? "the scan stopped (" + describe_snapshot(s) + ")" : s.message;
      all_failed = all_failed && s.state == LinkState::Failed;
      if (stopped_here && !reconnect) failure = stopped;
    }
    if (all_failed) failure = stopped;
    if (!failure.empty()) break;
    const double elapsed = scan_start ? std::chrono::duration<double>(Clock::now() - *scan_start).count() : 0.0;
    if (seconds && scan_start && elapsed >= *seconds) break;
    if (tty && Clock::now() - last_progress >= std::chrono::milliseconds(250)) {
      show_progress(shown, elapsed, set);
      last_progress = Clock::now();
    }
  }
  if (tty) std::fputs("\r\033[K", stderr);

  // Close the files first (every tap's last records in them), then stop the lidars. Each lidar's
  // taps close together, so the .ydrec and the MCAP end at the same byte of it.
  std::vector<std::future<CommandResult>> closed = close_run_taps(set.sessions(), recording.get(), live.get());
  if (live && !live->stop() && failure.empty()) failure = live->error();
  for (auto& tap_closed : closed) tap_closed.wait();
  if (recording && !recording->finish() && failure.empty()) failure = recording->error();
  set.disconnect_all();

  bool health_error = false;
  bool any_bytes = false;
  for (std::size_t id = 0; id < set.size(); ++id) {
    const auto c = set.session(id).snapshot().counters;
    std::fputs(checksum_warning(watches[id].program, c.packets, c.checksum_errors).c_str(), stderr);
    any_bytes = any_bytes || c.bytes_received > 0 || c.bytes_sent > 0;
    health_error = health_error || watches[id].health->worst() == HealthLevel::Error;
  }
  std::optional<RecordingSummary> summary;
  if (recording) {
    if (recording->dropped())
      std::fprintf(stderr, "ydscope-cli record: warning: %s lacks %llu records: writing it fell behind the lidar\n",
                   out->c_str(), static_cast<unsigned long long>(recording->dropped()));
    summary = summarize_recording(*out, error);
    if (!summary) throw std::runtime_error(error);
    any_bytes = summary->device_bytes > 0 || summary->host_bytes > 0;
  }
  if (!any_bytes) {  // no port ever opened: an empty recording helps nobody
    if (out) std::filesystem::remove(*out);
    if (mcap_path) std::filesystem::remove(*mcap_path);
    throw std::runtime_error(failure.empty() ? "no lidar answered; nothing was recorded" : failure);
  }
  if (summary) print_recording_summary(*out, set, watches, *summary);
  if (live) {
    std::printf("%s%s\n", live->file_summary().c_str(),
                summary || several ? "" : watches[0].health->summary_note().c_str());
    if (live->dropped())
      std::fprintf(stderr, "ydscope-cli record: warning: %s lacks %llu records: writing it fell behind the lidar\n",
                   mcap_path->c_str(), static_cast<unsigned long long>(live->dropped()));
  }
  std::fflush(stdout);
  if (!failure.empty()) throw std::runtime_error(failure + "; what was recorded until then is in " + shown);
  for (std::size_t id = 0; id < set.size(); ++id)
    if (!set.ever_scanned(id) && several)
      throw std::runtime_error(
          who(set, id) + " never scanned (" +
          (watches[id].notes->last_problem().empty() ? "no reason given" : watches[id].notes->last_problem()) +
          "); the other lidars are in " + shown);
  return health_error ? kExitLidarFault : kExitOk;
}

}  // namespace ydscope::cli
