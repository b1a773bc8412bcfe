#include "core/session/session_recorder.h"

#include <algorithm>

#include "core/session/record_tap.h"
#include "core/session/session_io.h"
#include "core/record/recording_writer.h"

namespace ydscope {

SessionRecorder::SessionRecorder() = default;
SessionRecorder::~SessionRecorder() {
  stop();
  for (Tap& t : taps_) t.tap->close();
}

void SessionRecorder::start_tap(std::shared_ptr<RecordTap> tap, RecordingMetadata metadata) {
  stop_tap(*tap);  // the same tap twice would get every record twice
  if (!metadata.start_wall_time) metadata.start_wall_time = iso8601_utc_now();
  const std::string text = metadata.encode();
  tap->push(RecordType::Metadata, {reinterpret_cast<const std::uint8_t*>(text.data()), text.size()}, 0);
  const std::int64_t start_ns = tap->epoch_ns().value_or(link_clock_ns());  // a shared epoch: one timeline
  taps_.push_back({std::move(tap), start_ns});
}

bool SessionRecorder::stop_tap(const RecordTap& tap) {
  const auto it = std::find_if(taps_.begin(), taps_.end(), [&](const Tap& t) { return t.tap.get() == &tap; });
  if (it == taps_.end()) return false;
  it->tap->close();
  taps_.erase(it);
  return true;
}

bool SessionRecorder::start(const std::string& path, const RecordingMetadata& metadata, std::string& error) {
  stop();
  error_.clear();
  if (error = recording_output_problem(path); !error.empty()) return false;
  writer_ = RecordingWriter::create(path, metadata, link_clock_ns(), error);
  if (!writer_) return false;
  path_ = path;
  return true;
}

void SessionRecorder::stop() {
  if (!writer_) return;
  if (!writer_->close() && error_.empty()) error_ = writer_->error();
  writer_.reset();
}

void SessionRecorder::bytes(bool outgoing, std::span<const std::uint8_t> data, std::int64_t now_ns) {
  if (!data.empty())
    for (const Tap& t : taps_)
      t.tap->push(outgoing ? RecordType::HostToDevice : RecordType::DeviceToHost, data,
                  std::max<std::int64_t>(0, now_ns - t.start_ns));
  if (!writer_) return;
  if (!writer_->append(outgoing ? Direction::HostToDevice : Direction::DeviceToHost, data, now_ns)) {
    error_ = writer_->error();
    writer_.reset();
  }
}

void SessionRecorder::metadata(const RecordingMetadata& metadata) {
  if (!taps_.empty()) {
    const std::string text = metadata.encode();
    const std::int64_t now = link_clock_ns();
    for (const Tap& t : taps_)
      t.tap->push(RecordType::Metadata, {reinterpret_cast<const std::uint8_t*>(text.data()), text.size()},
                  std::max<std::int64_t>(0, now - t.start_ns));
  }
  if (!writer_) return;
  if (!writer_->update_metadata(metadata, link_clock_ns())) {
    error_ = writer_->error();
    writer_.reset();
  }
}

void SessionRecorder::flush() {
  if (writer_ && !writer_->flush()) {
    error_ = writer_->error();
    writer_.reset();
  }
}

std::uint64_t SessionRecorder::file_size() const { return writer_ ? writer_->file_size() : 0; }

}  // namespace ydscope
