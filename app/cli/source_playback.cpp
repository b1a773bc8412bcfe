#include "app/cli/source_playback.h"

#include <algorithm>
#include <chrono>
#include <stdexcept>
#include <thread>

#include "app/cli/recording_input.h"
#include "core/record/recording_reader.h"
#include "core/record/source_decoders.h"

namespace ydscope::cli {
namespace {

using Clock = std::chrono::steady_clock;

// Sleeps until `due`, in short steps so Ctrl-C is noticed. False when stopped.
bool wait_until(Clock::time_point due, const std::atomic<bool>& stop) {
  while (!stop.load()) {
    const auto left = due - Clock::now();
    if (left <= Clock::duration::zero()) return true;
    std::this_thread::sleep_for(std::min<Clock::duration>(left, std::chrono::milliseconds(100)));
  }
  return false;
}

}  // namespace

void print_source_laps(const std::string& path, const RecordingPlan& plan, LapFormat format, Pacing pacing,
                       InterferenceFilter filter, const std::atomic<bool>& stop) {
  const double speed = pacing.speed;
  std::string error;
  auto reader = RecordingReader::open(path, error);
  if (!reader) throw std::runtime_error(error);  // the file changed since the plan read it

  SourceDecoders decoders(plan.sources);
  JsonOut out(stdout);
  LapPrinter printer(out, format, false);
  Lap filtered;
  const auto on_lap = [&](std::size_t source, const Lap& lap) {
    const SourcePlan& from = plan.sources[source];
    if (!filter.any()) {
      printer.print_from(from.name, from.profile->ct_carries_info, lap);
    } else {
      filtered = lap;
      filter_interference(filtered, filter);
      printer.print_from(from.name, from.profile->ct_carries_info, filtered);
    }
    if (speed > 0) out.flush();  // a program reading the pipe gets each lap as it is played
  };

  const auto start = Clock::now();
  std::int64_t last_device_t = 0;
  std::int64_t skipped_ns = 0;  // gaps skipped so far: later records play that much earlier
  RecordView record;
  while (!stop.load() && reader->next(record)) {
    if (speed > 0 && record.type == RecordType::DeviceToHost) {
      if (const auto gap = long_gap(last_device_t, record.t_ns)) {
        if (!pacing.keep_gaps) skipped_ns += gap->length_ns;
        print_gap("ydscope-cli replay", *gap, !pacing.keep_gaps);
      }
      last_device_t = record.t_ns;
      const auto due = start + std::chrono::nanoseconds(
                                   static_cast<std::int64_t>(static_cast<double>(record.t_ns - skipped_ns) / speed));
      if (!wait_until(due, stop)) break;
    }
    decoders.feed(record, on_lap);
  }
  decoders.finish(on_lap);
  if (printer.wants_summary())
    for (std::size_t source = 0; source < decoders.size(); ++source)
      write_summary(out, decoders.decoder(source)->counters(), plan.summary.sources[source].metadata.start_wall_time,
                    plan.sources[source].name);
  out.flush();
}

}  // namespace ydscope::cli
