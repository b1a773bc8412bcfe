#include "core/session/sources_recording.h"

#include <algorithm>
#include <string_view>

#include "core/session/session_io.h"

namespace ydscope {

std::unique_ptr<SourcesRecording> SourcesRecording::create(const std::string& path,
                                                           std::vector<RecordingMetadata> sources, std::string& error) {
  if (error = recording_output_problem(path); !error.empty()) return nullptr;
  const std::size_t count = sources.size();
  const std::int64_t epoch = link_clock_ns();
  auto writer = RecordingWriter::create_sources(path, std::move(sources), epoch, error);
  if (!writer) return nullptr;
  return std::unique_ptr<SourcesRecording>(new SourcesRecording(std::move(writer), epoch, count));
}

SourcesRecording::SourcesRecording(std::unique_ptr<RecordingWriter> writer, std::int64_t epoch_ns, std::size_t sources)
    : writer_(std::move(writer)), epoch_ns_(epoch_ns) {
  for (std::size_t i = 0; i < sources; ++i) taps_.push_back(std::make_shared<RecordTap>(64u << 20, epoch_ns));
}

void SourcesRecording::take_from_taps(std::chrono::milliseconds wait) {
  for (std::size_t id = 0; id < taps_.size(); ++id) {
    // Only the first tap waits: the others are read right after, whatever it had.
    taps_[id]->wait_and_take(taken_, id == 0 ? wait : std::chrono::milliseconds(0));
    for (TapRecord& record : taken_)
      pending_.push_back({record.t_ns, arrivals_++, static_cast<std::uint16_t>(id), record.type,
                          std::vector<std::uint8_t>(record.payload.begin(), record.payload.end())});
    taps_[id]->recycle(taken_);
  }
}

bool SourcesRecording::write_up_to(std::int64_t t_ns) {
  std::sort(pending_.begin(), pending_.end(),
            [](const Pending& a, const Pending& b) { return a.t_ns != b.t_ns ? a.t_ns < b.t_ns : a.order < b.order; });
  std::size_t written = 0;
  for (; written < pending_.size() && pending_[written].t_ns <= t_ns; ++written) {
    const Pending& record = pending_[written];
    const std::int64_t at = epoch_ns_ + record.t_ns;
    if (record.type == RecordType::Metadata) {
      // A session's own metadata (model, baud, device info); the file's start time stays the one
      // all sources share.
      RecordingMetadata metadata = RecordingMetadata::parse(
          std::string_view(reinterpret_cast<const char*>(record.payload.data()), record.payload.size()));
      metadata.start_wall_time.reset();
      if (!writer_->update_metadata(metadata, at, record.source)) return false;
    } else if (!writer_->append(static_cast<Direction>(record.type), record.payload, at, record.source)) {
      return false;
    }
  }
  pending_.erase(pending_.begin(), pending_.begin() + static_cast<std::ptrdiff_t>(written));
  return true;
}

bool SourcesRecording::pump(std::chrono::milliseconds wait) {
  if (writer_->failed()) return false;
  take_from_taps(wait);
  // One tap's records come in order from one I/O thread: only several need the wait.
  const auto hold = taps_.size() > 1 ? std::chrono::duration_cast<std::chrono::nanoseconds>(kHoldBack).count() : 0;
  return write_up_to(link_clock_ns() - epoch_ns_ - hold);
}

bool SourcesRecording::finish() {
  take_from_taps(std::chrono::milliseconds(0));
  if (!writer_->failed()) write_up_to(INT64_MAX);
  return writer_->close();
}

std::uint64_t SourcesRecording::dropped() const {
  std::uint64_t total = 0;
  for (const auto& tap : taps_) total += tap->dropped();
  return total;
}

}  // namespace ydscope
