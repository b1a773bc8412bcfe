#pragma once
// SessionRecorder: the session's use of the recording writer, and of a live RecordTap. It lives
// on the I/O thread, so every byte read or written is recorded as it crosses the link and nothing
// can be lost to the UI. The file and the taps are independent: any of them, or none. Several
// taps, because their consumers come and go on their own (the app shares its source over the
// Foxglove bridge while an MCAP recording of it starts and stops).
#include <cstdint>
#include <memory>
#include <span>
#include <string>
#include <vector>

#include "core/record/recording_metadata.h"

namespace ydscope {

class RecordingWriter;
class RecordTap;

class SessionRecorder {
 public:
  SessionRecorder();
  ~SessionRecorder();

  // Opens `path` and writes the header and `metadata`. False plus one sentence on failure.
  bool start(const std::string& path, const RecordingMetadata& metadata, std::string& error);
  void stop();
  bool active() const { return writer_ != nullptr; }
  // Adds a tap: it gets a metadata record (`metadata` plus its start time) and then every record.
  void start_tap(std::shared_ptr<RecordTap> tap, RecordingMetadata metadata);
  // Closes `tap` and forgets it; false when it was not one of ours.
  bool stop_tap(const RecordTap& tap);
  bool tapping() const { return !taps_.empty(); }
  // Anything wants the link's bytes.
  bool capturing() const { return writer_ || !taps_.empty(); }
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
  struct Tap {
    std::shared_ptr<RecordTap> tap;
    std::int64_t start_ns = 0;  // its records' times count from here
  };
  std::vector<Tap> taps_;
  std::string path_;
  std::string error_;
};

}  // namespace ydscope
