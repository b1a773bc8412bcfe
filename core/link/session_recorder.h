#pragma once
// SessionRecorder: the session's use of the recording writer. It lives on the I/O thread, so every
// byte read or written is recorded as it crosses the link and nothing can be lost to the UI.
#include <cstdint>
#include <memory>
#include <span>
#include <string>

#include "core/record/recording_metadata.h"

namespace ydscope {

class RecordingWriter;

class SessionRecorder {
 public:
  SessionRecorder();
  ~SessionRecorder();

  // Opens `path` and writes the header and `metadata`. False plus one sentence on failure.
  bool start(const std::string& path, const RecordingMetadata& metadata, std::string& error);
  void stop();
  bool active() const { return writer_ != nullptr; }
  const std::string& path() const { return path_; }

  void bytes(bool outgoing, std::span<const std::uint8_t> data, std::int64_t now_ns);
  void metadata(const RecordingMetadata& metadata);
  // Hands buffered bytes to the kernel while the link is quiet (the session's tick calls it).
  void flush();
  std::uint64_t file_size() const;
  // The first write error, as a sentence; recording stops at it.
  const std::string& error() const { return error_; }

 private:
  std::unique_ptr<RecordingWriter> writer_;
  std::string path_;
  std::string error_;
};

}  // namespace ydscope
