#include "core/link/session_recorder.h"

#include "core/link/session_io.h"
#include "core/record/recording_writer.h"

namespace ydscope {

SessionRecorder::SessionRecorder() = default;
SessionRecorder::~SessionRecorder() { stop(); }

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
  if (!writer_) return;
  if (!writer_->append(outgoing ? Direction::HostToDevice : Direction::DeviceToHost, data, now_ns)) {
    error_ = writer_->error();
    writer_.reset();
  }
}

void SessionRecorder::metadata(const RecordingMetadata& metadata) {
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
