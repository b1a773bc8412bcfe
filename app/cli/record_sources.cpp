#include "app/cli/record_sources.h"

#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <filesystem>
#include <functional>
#include <future>
#include <memory>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

#include "app/cli/cli_command.h"
#include "app/cli/health_watch.h"
#include "app/cli/mcap_output.h"
#include "app/cli/recording_input.h"
#include "app/cli/link_loss_notes.h"
#include "app/cli/source_options.h"
#include "core/record/recorded_conventions.h"
#include "core/bridge/live_topics.h"
#include "core/link/sources_recording.h"
#include "core/record/recording_reader.h"
#include "core/record/source_decoders.h"

namespace ydscope::cli {
namespace {

using Clock = std::chrono::steady_clock;

// A lidar that stalls or drops gets this long to come back (the session reconnects by itself)
// before the recording waits on without it; it keeps trying all along.
constexpr std::chrono::seconds kSettlePatience{60};

// One lidar of the recording, as the CLI watches it.
struct Source {
  SourceSpec spec;
  std::unique_ptr<Session> session;
  std::unique_ptr<HealthWatch> health;
  LinkLossNotes notes;
};

CommandResult wait_for(const std::function<void(CommandCallback)>& post) {
  std::promise<CommandResult> promise;
  auto result = promise.get_future();
  post([&promise](const CommandResult& r) { promise.set_value(r); });
  return result.get();
}

// "NAME (PORT)": how every line names a lidar.
std::string who(const SourceSpec& spec) { return spec.name + " (" + spec.config.address + ")"; }

void show_progress(const std::string& out, double seconds, const std::vector<Source>& sources) {
  std::string line;
  for (const Source& source : sources) {
    const SessionSnapshot s = source.session->snapshot();
    line += ", " + source.spec.name + " " + std::to_string(s.counters.laps) + " laps" +
            (scanning(s.state) ? "" : " (" + std::string(link_state_name(s.state)) + ")");
  }
  std::fprintf(stderr, "\r\033[Krecording %s: %.1f s%s", out.c_str(), seconds, line.c_str());
  std::fflush(stderr);
}

// Per source: ", L laps" decoded from the finished file, as a replay will give them.
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

// What the .ydrec holds, per lidar, as replay will decode it.
void print_recording_summary(const std::string& out, const std::vector<Source>& sources,
                             const RecordingSummary& summary) {
  const auto laps = laps_per_source(out, summary);
  std::printf("recorded %s: %.1f s, %zu lidars\n", out.c_str(), static_cast<double>(summary.duration_ns) / 1e9,
              sources.size());
  for (std::size_t id = 0; id < sources.size(); ++id) {
    const SourceSummary& s = summary.sources.at(id);
    std::printf("  %s: %s on %s, %llu bytes from the device, %llu bytes to it, %llu laps%s\n",
                sources[id].spec.name.c_str(), s.metadata.model.value_or("unknown model").c_str(),
                sources[id].spec.config.address.c_str(), static_cast<unsigned long long>(s.device_bytes),
                static_cast<unsigned long long>(s.host_bytes), static_cast<unsigned long long>(laps[id]),
                sources[id].health->summary_note().c_str());
  }
  print_recording_warnings("ydscope-cli record", summary.damage);
}

}  // namespace

int record_sources(const Arguments& args, const std::atomic<bool>& interrupted) {
  const auto out = args.value("out");
  const auto mcap_path = args.value("mcap");
  if (!out && !mcap_path) throw UsageError("say where to record: --out FILE.ydrec, --mcap FILE.mcap, or both");
  if (out && mcap_path && *out == *mcap_path) throw UsageError("--out and --mcap must be different files");
  if (mcap_path) refuse_to_overwrite(*mcap_path, args, "--mcap");
  const auto seconds = args.number("seconds", 0.001, 1e7);
  std::vector<Source> sources;
  std::vector<RecordingMetadata> metadata;
  for (SourceSpec& spec : source_specs_from(args, /*scan=*/true)) {
    spec.config.reconnect = true;  // one lidar's fault must not end the others' recording
    metadata.push_back(source_metadata(spec));
    LinkLossNotes notes("ydscope-cli record", who(spec), "the other lidars keep recording");
    sources.push_back({std::move(spec), nullptr, nullptr, std::move(notes)});
  }
  if (out)
    if (const std::string problem = recording_output_problem(*out); !problem.empty()) throw UsageError(problem);
  const bool tty = ::isatty(STDERR_FILENO) == 1;
  const std::string shown = out.value_or(mcap_path.value_or(""));

  std::string error;
  std::unique_ptr<SourcesRecording> recording;
  if (out) {
    recording = SourcesRecording::create(*out, std::move(metadata), error);
    if (!recording) throw std::runtime_error(error);
  }
  for (Source& source : sources) {
    source.session = std::make_unique<Session>(4);
    source.health = std::make_unique<HealthWatch>("ydscope-cli record: " + source.spec.name);
    source.health->clear_line_first(tty);
  }
  // The MCAP file is written from taps of its own, on a thread of its own (/NAME/scan ...).
  std::unique_ptr<LiveTopics> live;
  if (mcap_path) {
    std::vector<LiveSource> live_sources;
    for (const Source& source : sources)
      live_sources.push_back({source.session.get(), {source.spec.name, source.spec.pose, source.spec.config.model}});
    LiveTopicsOptions options;
    options.topics = mcap_options_from(args);
    options.mcap_path = *mcap_path;
    options.attach = false;  // each session's tap right after its connect, below
    live = LiveTopics::start(std::move(live_sources), std::move(options), error);
    if (!live) throw std::runtime_error(error);
  }
  for (std::size_t id = 0; id < sources.size(); ++id) {
    Source& source = sources[id];
    // Both taps before the connect intent (they run in order on its I/O thread), so the start-up
    // exchange is in the .ydrec and the MCAP file alike: a tap posted after the connect missed
    // the first A5 65 whenever the connect's first write came before it (seen under ASan).
    if (live) live->attach_source(id);
    if (recording)
      wait_for([&](CommandCallback done) { source.session->start_tap(recording->tap(id), std::move(done)); });
    source.session->connect(source.spec.config);
  }

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
    bool settled = true;
    for (Source& source : sources) {
      if (source.session->laps().drain_newest(lap) > 0) source.health->observe_lap(lap);
      const SessionSnapshot s = source.session->snapshot();
      source.health->observe_answer(s.health);
      source.notes.follow(s, tty);
      settled = settled && (source.notes.ever_scanned() || source.notes.down());
    }
    // --seconds counts from when every lidar scans (or was said to be in trouble).
    if (!scan_start && (settled || Clock::now() - start > kSettlePatience)) scan_start = Clock::now();
    const double elapsed = scan_start ? std::chrono::duration<double>(Clock::now() - *scan_start).count() : 0.0;
    if (seconds && scan_start && elapsed >= *seconds) break;
    if (tty && Clock::now() - last_progress >= std::chrono::milliseconds(250)) {
      show_progress(shown, elapsed, sources);
      last_progress = Clock::now();
    }
  }
  if (tty) std::fputs("\r\033[K", stderr);

  // Close the files first (every tap's last records in them), then stop the lidars. Every tap's
  // close is asked for before waiting on any, so the .ydrec and the MCAP end at the same byte of
  // each lidar (each session closes its taps in the order asked, between two reads).
  std::vector<std::future<CommandResult>> closed;
  if (recording)
    for (std::size_t id = 0; id < sources.size(); ++id) {
      auto promise = std::make_shared<std::promise<CommandResult>>();
      closed.push_back(promise->get_future());
      sources[id].session->stop_tap(recording->tap(id), [promise](const CommandResult& r) { promise->set_value(r); });
    }
  if (live && !live->stop() && failure.empty()) failure = live->error();
  for (auto& tap_closed : closed) tap_closed.wait();
  if (recording && !recording->finish() && failure.empty()) failure = recording->error();
  for (Source& source : sources) source.session->disconnect();
  for (Source& source : sources)
    source.session->wait_until(
        [](const SessionSnapshot& x) { return x.state == LinkState::Idle || x.state == LinkState::Failed; },
        std::chrono::seconds(3));

  bool health_error = false;
  bool any_bytes = false;
  for (const Source& source : sources) {
    const auto c = source.session->snapshot().counters;
    any_bytes = any_bytes || c.bytes_received > 0 || c.bytes_sent > 0;
    health_error = health_error || source.health->worst() == HealthLevel::Error;
  }
  std::optional<RecordingSummary> summary;
  if (recording) {
    if (recording->dropped())
      std::fprintf(stderr, "ydscope-cli record: warning: %s lacks %llu records: writing it fell behind the lidars\n",
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
  if (summary) print_recording_summary(*out, sources, *summary);
  if (live) {
    std::printf("%s\n", live->file_summary().c_str());
    if (live->dropped())
      std::fprintf(stderr, "ydscope-cli record: warning: %s lacks %llu records: writing it fell behind the lidars\n",
                   mcap_path->c_str(), static_cast<unsigned long long>(live->dropped()));
  }
  std::fflush(stdout);
  if (!failure.empty()) throw std::runtime_error(failure + "; what was recorded until then is in " + shown);
  for (const Source& source : sources)
    if (!source.notes.ever_scanned())
      throw std::runtime_error(who(source.spec) + " never scanned (" +
                               (source.notes.last_problem().empty() ? "no reason given" : source.notes.last_problem()) +
                               "); the other lidars are in " + shown);
  return health_error ? kExitLidarFault : kExitOk;
}

}  // namespace ydscope::cli
