#include "core/link/session_recorder.h"

#include <algorithm>

#include "core/link/record_tap.h"
#include "core/link/session_io.h"
#include "core/record/recording_writer.h"

namespace ydscope {

SessionRecorder::SessionRecorder() = default;
SessionRecorder::~SessionRecorder() {
  stop();
  stop_tap();
}

void SessionRecorder::start_tap(std::shared_ptr<RecordTap> tap, RecordingMetadata metadata) {
  stop_tap();
  tap_ = std::move(tap);
  tap_start_ns_ = link_clock_ns();
  if (!metadata.start_wall_time) metadata.start_wall_time = iso8601_utc_now();
  const std::string text = metadata.encode();
  tap_->push(RecordType::Metadata, {reinterpret_cast<const std::uint8_t*>(text.data()), text.size()}, 0);
}

void SessionRecorder::stop_tap() {
  if (!tap_) return;
  tap_->close();
  tap_.reset();
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
  if (tap_ && !data.empty())
    tap_->push(outgoing ? RecordType::HostToDevice : RecordType::DeviceToHost, data, std::max<std::int64_t>(0, now_ns - tap_start_ns_));
  if (!writer_) return;
  if (!writer_->append(outgoing ? Direction::HostToDevice : Direction::DeviceToHost, data, now_ns)) {
    error_ = writer_->error();
    writer_.reset();
  }
}

void SessionRecorder::metadata(const RecordingMetadata& metadata) {
  if (tap_) {
    const std::string text = metadata.encode();
    tap_->push(RecordType::Metadata, {reinterpret_cast<const std::uint8_t*>(text.data()), text.size()},
               std::max<std::int64_t>(0, link_clock_ns() - tap_start_ns_));
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
