#pragma once
// McapRecordingExport: a recording's records in, an MCAP file (profile ros2) out. The same path
// serves `ydscope-cli export` (records read from a .ydrec), `record --mcap` (the live session's
// record tap) and `decode --mcap` (raw bytes with synthetic times). Schemas and channels are
// written up front; each metadata record becomes an MCAP Metadata record "ydscope.recording"
// with every key merged so far (the last one is complete), so the link-byte channels decode
// again exactly like a .ydrec. Not thread-safe.
#include <cstdint>
#include <functional>
#include <memory>
#include <span>
#include <string>

#include "core/export/mcap_sink.h"
#include "core/export/mcap_writer.h"
#include "core/export/ros_topic_encoder.h"
#include "core/record/recording_format.h"

namespace ydscope {

struct McapExportOptions {
  RosExportOptions ros;
  McapWriterOptions mcap;
};

inline constexpr const char* kMcapRecordingMetadataName = "ydscope.recording";

class McapRecordingExport {
 public:
  // Creates `path`; null plus one sentence in `error` when it cannot be created.
  static std::unique_ptr<McapRecordingExport> create(const std::string& path, const McapExportOptions& options,
                                                     std::string& error);
  // Writes into `sink`, which must outlive the export (tests and fuzzing use a memory sink).
  McapRecordingExport(McapSink& sink, const McapExportOptions& options);

  // One record as a .ydrec holds it: link bytes (either direction) or a metadata payload
  // (key=value text). Records of unknown types are ignored, as readers of .ydrec do.
  void record(RecordType type, std::span<const std::uint8_t> payload, std::int64_t t_ns);
  void metadata(const RecordingMetadata& changes, std::int64_t t_ns);
  // A lap decoded elsewhere (the app's shown laps): its /scan and /points, stamped `stamp_ns`
  // (ns since the Unix epoch); `scan_time_s` is the time since the previous lap's close (0: unknown).
  void lap(const Lap& lap, Model model, std::uint64_t stamp_ns, double scan_time_s);
  // Closes the open chunk so what was written so far is readable (call at least once a second live).
  bool flush();
  // Last laps and diagnostics, summary and footer. False plus error() if anything failed.
  bool finish();

  bool failed() const { return writer_.failed() || (file_ && !file_->error().empty()); }
  // The first failure: the writer's, or closing the file's.
  const std::string& error() const { return writer_.failed() || !file_ ? writer_.error() : file_->error(); }
  const McapStatistics& statistics() const { return writer_.statistics(); }
  std::uint64_t bytes_written() const { return writer_.bytes_written(); }
  RosTopicEncoder& encoder() { return encoder_; }
  // Also sees every message written (the bridge serves them while they are recorded).
  using Observer = std::function<void(RosTopic, std::uint64_t log_time, std::span<const std::uint8_t> cdr)>;
  void set_observer(Observer observer) { observer_ = std::move(observer); }

 private:
  McapRecordingExport(std::unique_ptr<McapFileSink> file, const McapExportOptions& options);
  void emit(RosTopic topic, std::uint64_t log_time, std::span<const std::uint8_t> cdr);

  std::unique_ptr<McapFileSink> file_;  // when the export owns its file
  McapWriter writer_;
  RosTopicEncoder encoder_;
  RosFrameOptions frame_;
  std::vector<float> scan_scratch_;  // lap()'s
  std::vector<std::uint8_t> message_;
  std::uint16_t channel_[kRosTopicCount] = {};
  std::uint32_t sequence_[kRosTopicCount] = {};
  bool finished_ = false;
  Observer observer_;
};

// The channel metadata the ros2 profile requires: offered_qos_profiles as rosbag2 writes it
// (keep-last, reliable, volatile), so `ros2 bag play` republishes with a matching QoS.
const McapMetadataMap& ros2_channel_metadata();

}  // namespace ydscope
