#pragma once
// SourcesRecording: several sessions (one per lidar) recorded into ONE .ydrec file, each a source
// of its own (recording format version 2; a single source writes version 1, as ever).
//
// Each session runs on its own I/O thread and hands its records to a RecordTap this object made;
// the taps share one epoch, so their times are one timeline. pump() runs on one consumer thread
// (the CLI's): it takes what the taps hold and writes it in time order. A record waits kHoldBack
// before it is written, so a record another I/O thread pushes a little late still goes in its
// place (the file's times never go back); a single source's records, all from one thread, are
// written as they come.
#include <chrono>
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "core/session/record_tap.h"
#include "core/record/recording_metadata.h"
#include "core/record/recording_writer.h"

namespace ydscope {

class SourcesRecording {
 public:
  static constexpr std::chrono::milliseconds kHoldBack{500};

  // Creates `path` with one metadata record per source (name, pose, port, ...). Null plus one
  // sentence in `error` on failure.
  static std::unique_ptr<SourcesRecording> create(const std::string& path, std::vector<RecordingMetadata> sources,
                                                  std::string& error);

  // The tap to give source `id`'s session (Session::start_tap).
  const std::shared_ptr<RecordTap>& tap(std::size_t id) const { return taps_.at(id); }
  // Waits up to `wait` for records, writes those older than kHoldBack. False once writing failed.
  bool pump(std::chrono::milliseconds wait);
  // After every session stopped its tap: writes everything left and closes the file. False (and
  // error()) when any write failed.
  bool finish();

  const std::string& error() const { return writer_->error(); }
  const std::string& path() const { return writer_->path(); }
  // Records a tap could not take because this fell behind, over every source.
  std::uint64_t dropped() const;

 private:
  struct Pending {
    std::int64_t t_ns;
    std::uint64_t order;  // arrival order, so equal times keep it
    std::uint16_t source;
    RecordType type;
    std::vector<std::uint8_t> payload;
  };
  SourcesRecording(std::unique_ptr<RecordingWriter> writer, std::int64_t epoch_ns, std::size_t sources);
  void take_from_taps(std::chrono::milliseconds wait);
  bool write_up_to(std::int64_t t_ns);

  std::unique_ptr<RecordingWriter> writer_;
  std::int64_t epoch_ns_;
  std::vector<std::shared_ptr<RecordTap>> taps_;
  std::vector<TapRecord> taken_;
  std::vector<Pending> pending_;
  std::uint64_t arrivals_ = 0;
};

}  // namespace ydscope
