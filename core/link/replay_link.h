#pragma once
// ReplayLink: a ByteLink that plays back the device->host bytes of a recording (.ydrec), with
// the original timing scaled by a speed (1 = as recorded, 4 = four times faster, 0 = as fast as
// the reader takes them), pause/resume and loop. There is no device behind it: writes are
// accepted and dropped, accepts_commands() is false, set_baud() is refused.
//
// Threads: the ByteLink calls (async_read_some, async_write, close) belong to the thread running
// the io_context, like every ByteLink. The controls (set_speed, set_paused, set_loop, restart)
// may be called from any thread: they are posted to the io_context. status() may be read from
// any thread (a copy taken under a lock). The link may be destroyed on any thread (its playback
// is closed on the io_context's thread), as long as the io_context outlives it.
#include <cstdint>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include <boost/asio/io_context.hpp>

#include "core/link/byte_link.h"
#include "core/record/recording_gap.h"
#include "core/record/recording_metadata.h"
#include "core/record/recording_reader.h"

namespace ydscope {

// Speeds besides 0 (as fast as possible) are held to this range: a thousandth of the recorded
// pace is already 17 minutes for each second recorded.
inline constexpr double kMinReplaySpeed = 0.001;
inline constexpr double kMaxReplaySpeed = 1e6;
// speed as ReplayLink uses it: negative 0, NaN 1, others clamped into [kMinReplaySpeed, kMaxReplaySpeed].
double bounded_replay_speed(double speed);

struct ReplayOptions {
  double speed = 1.0;  // 1 original timing, >1 faster, <1 slower, 0 as fast as possible
  bool loop = false;   // start again at the end instead of reporting end-of-file
  bool paused = false;
  // A recording of several lidars (format version 2): the one whose bytes play; the others' are
  // passed over, so one link never mixes two lidars' streams. Version 1 has only source 0.
  std::uint16_t source = 0;
  // A gap longer than kLongGapNs (core/record/recording_gap.h) is skipped, or with false waited
  // out as recorded; either way on_gap hears of it (I/O thread) when playback reaches it. A gap
  // means nothing at speed 0, where nothing waits.
  bool skip_gaps = true;
  std::function<void(const RecordingGap&, bool skipped)> on_gap = nullptr;
};

struct ReplayStatus {
  std::int64_t position_ns = 0;  // recording time of the playback point
  std::int64_t duration_ns = 0;  // recording time of the last record
  double speed = 1.0;
  bool paused = false;
  bool loop = false;
  bool finished = false;    // reached the end without loop (reads now see end-of-file)
  std::uint64_t loops = 0;  // times playback wrapped around
  std::uint64_t bytes = 0;  // device->host bytes delivered
  std::uint64_t gaps = 0;   // long gaps reached so far (this pass and earlier ones)
  RecordingGap last_gap;    // the latest of them
  bool skip_gaps = true;
};

class ReplayLink final : public ByteLink {
 public:
  // Opens the recording and reads its metadata (a pass over the file). Null plus one sentence
  // in `error` when it is missing, not a recording (or one this ydscope cannot read: `failure`
  // says which, RecordingReader::open), or has no device->host bytes at all.
  static std::unique_ptr<ReplayLink> open(boost::asio::io_context& io, const std::string& path, ReplayOptions options,
                                          std::string& error, RecordingOpenFailure* failure = nullptr);
  ~ReplayLink() override;

  // Completes with the next recorded bytes when their time comes; boost::asio::error::eof after
  // the last one (unless looping); operation_aborted after close().
  void async_read_some(std::span<std::uint8_t> buffer, IoHandler handler) override;
  // Completes at once with every byte "written"; they go nowhere.
  void async_write(std::span<const std::uint8_t> bytes, IoHandler handler) override;
  void close() override;
  bool set_baud(std::uint32_t baud, std::string& error) override;
  bool accepts_commands() const override { return false; }
  std::string describe() const override;

  // Controls, any thread.
  void set_speed(double speed);  // through bounded_replay_speed()
  void set_paused(bool paused);
  void set_loop(bool loop);
  void restart();  // back to the start of the recording, keeping speed/pause/loop

  ReplayStatus status() const;
  // I/O thread, in a read's completion handler: the recorded time of the bytes it delivered (a
  // read never spans two records), so a decoder stamps them as decode of the file would.
  std::int64_t recorded_time_of_last_read() const;
  // The recording's metadata, every metadata record merged (model, baud, device info...): of the
  // source that plays.
  const RecordingMetadata& metadata() const { return metadata_; }
  const RecordingMetadata* recording_metadata() const override { return &metadata_; }
  // What opening found wrong but playable, one sentence each: a truncated or corrupt tail,
  // damaged record times, damaged metadata fields. Empty when the file is sound.
  const std::vector<std::string>& warnings() const { return warnings_; }

  class Core;

 private:
  ReplayLink(std::shared_ptr<Core> core, std::string path, RecordingMetadata metadata,
             std::vector<std::string> warnings);

  std::shared_ptr<Core> core_;
  std::string path_;
  RecordingMetadata metadata_;
  std::vector<std::string> warnings_;
};

}  // namespace ydscope
