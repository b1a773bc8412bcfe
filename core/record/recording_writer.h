#pragma once
// RecordingWriter: appends link bytes and metadata to a .ydrec file (format in
// recording_format.h). Called on the session's I/O thread for every read and write, so an append
// is a copy into a buffer; the buffer goes to the kernel at least every 100 ms of recorded time
// (kFlushInterval), on every metadata record and on flush()/close(). Not thread-safe: one
// thread owns a writer.
//
// A write failure (disk full, file removed, ...) puts the writer into a failed state: later
// appends do nothing and return false, and error() says what happened in one sentence.
#include <cstdint>
#include <cstdio>
#include <memory>
#include <span>
#include <string>
#include <vector>

#include "core/record/recording_format.h"
#include "core/record/recording_metadata.h"

namespace ydscope {

// Why `path` cannot take a recording, in one sentence; empty when it can. A recording must be a
// regular file it can be read back from: a folder, a device such as /dev/null or a pipe is
// refused, and so is a path whose folder is missing or not writable. The session checks it when
// a recording starts, the CLI before it connects, so a user hears it at once.
std::string recording_output_problem(const std::string& path);

class RecordingWriter {
 public:
  static constexpr std::int64_t kFlushInterval = 100'000'000;  // ns of recorded time

  // Creates (or truncates) `path`, writes the file header and `metadata` as the first record.
  // `start_ns` is t=0 on the clock that append() timestamps use (the steady clock, as Lap
  // rx_ns). A missing start_wall_time is filled with the current time. Null plus one sentence in
  // `error` on failure. Any path the OS can write is taken (tests write /dev/full); sessions
  // check recording_output_problem() first.
  static std::unique_ptr<RecordingWriter> create(const std::string& path, RecordingMetadata metadata,
                                                 std::int64_t start_ns, std::string& error);
  // Several sources recorded at once, each with its metadata (name, pose, ...), by id: a
  // version-2 file, its metadata records first, one per source. With one source this is the
  // create() above: version 1, as a single lidar's file always was.
  static std::unique_ptr<RecordingWriter> create_sources(const std::string& path,
                                                         std::vector<RecordingMetadata> sources, std::int64_t start_ns,
                                                         std::string& error);
  ~RecordingWriter();  // close()
  RecordingWriter(const RecordingWriter&) = delete;
  RecordingWriter& operator=(const RecordingWriter&) = delete;

  // One record of link bytes seen at `t_ns` (same clock as start_ns; earlier times are clamped
  // so the file's times never go backwards). Empty spans are not recorded.
  // `source`: whose bytes, below source_count().
  bool append(Direction direction, std::span<const std::uint8_t> bytes, std::int64_t t_ns, std::uint16_t source = 0);
  // A metadata record with the fields that changed (e.g. device info); flushed at once.
  bool update_metadata(const RecordingMetadata& changes, std::int64_t t_ns, std::uint16_t source = 0);
  // Hands buffered records to the kernel (a periodic timer may call it while the link is quiet).
  bool flush();
  // Flushes and closes the file; later calls do nothing. Returns false if anything failed.
  bool close();

  bool failed() const { return !error_.empty(); }
  const std::string& error() const { return error_; }
  const std::string& path() const { return path_; }
  // Everything recorded so far, merged: source 0's, and each source's.
  const RecordingMetadata& metadata() const { return sources_.front(); }
  const RecordingMetadata& source_metadata(std::size_t source) const { return sources_.at(source); }
  std::size_t source_count() const { return sources_.size(); }
  std::uint64_t bytes(Direction direction) const;
  std::uint64_t records() const { return records_; }
  std::uint64_t file_size() const { return file_size_; }
  // Time of the last record, ns since start.
  std::int64_t duration_ns() const { return last_t_ns_; }

 private:
  RecordingWriter(std::FILE* file, std::string path, std::int64_t start_ns, std::size_t sources);
  bool write_record(RecordType type, std::span<const std::uint8_t> payload, std::int64_t t_ns, std::uint16_t source);
  bool known_source(std::uint16_t source);
  void fail(const std::string& what, int errno_value);

  std::FILE* file_;
  std::string path_;
  std::int64_t start_ns_;
  std::int64_t last_t_ns_ = 0;
  std::int64_t last_flush_t_ns_ = 0;
  std::uint64_t device_bytes_ = 0;
  std::uint64_t host_bytes_ = 0;
  std::uint64_t records_ = 0;
  std::uint64_t file_size_ = 0;
  std::vector<RecordingMetadata> sources_;
  std::string error_;
};

}  // namespace ydscope
