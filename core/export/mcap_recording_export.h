#pragma once
// McapRecordingExport: a recording's records in, an MCAP file (profile ros2) out. The same path
// serves `ydscope-cli export` (records read from a .ydrec), `record --mcap` (the live session's
// record tap) and `decode --mcap` (raw bytes with synthetic times). Schemas and channels are
// written up front; each metadata record becomes an MCAP Metadata record "ydscope.recording"
// with every key merged so far (the last one is complete), so the link-byte channels decode
// again exactly like a .ydrec. Not thread-safe.
//
// Several lidars (a version-2 recording): each source's topics go under its name (/NAME/scan,
// /NAME/points, /NAME/diagnostics, /NAME/ydscope/device_bytes, ...), its messages carry its name
// as frame_id, its metadata is the MCAP Metadata record "ydscope.recording.NAME", and /tf_static
// (tf2_msgs/msg/TFMessage) holds every pose as a transform from the common frame "ydscope" to the
// source's frame (core/export/ros_tf.h), written once before the first lap.
//
// Order: the file holds its messages in log-time order, as readers that stream a file expect
// (a lap is logged at its closing byte, after the bytes that came since; and several live lidars
// arrive from their taps in turns). Each message waits until every source's records have
// reached kHoldBackNs past its log time (or the newest source kHoldLimitNs past it, so a silent
// source holds nothing up for long); flush() and finish() write what is due.
#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "core/export/mcap_sink.h"
#include "core/export/mcap_writer.h"
#include "core/export/ros_topic_encoder.h"
#include "core/frame/source_info.h"
#include "core/record/recording_format.h"

namespace ydscope {

struct McapExportOptions {
  RosExportOptions ros;
  McapWriterOptions mcap;
};

inline constexpr const char* kMcapRecordingMetadataName = "ydscope.recording";

// Source `id`'s encoder options: its model when known (else base's, else the recording's), and
// when several are named apart, its frame as the frame id (one lidar keeps base's frame).
RosExportOptions ros_options_of(const RosExportOptions& base, std::span<const SourceInfo> sources, std::size_t id);
// A topic's name: "/scan" for one lidar (a set of one, or none given), "/NAME/scan" for one of several.
std::string source_topic_name(std::span<const SourceInfo> sources, std::size_t id, std::string_view topic);

class McapRecordingExport {
 public:
  static constexpr std::uint64_t kHoldBackNs = 500'000'000;
  static constexpr std::uint64_t kHoldLimitNs = 5'000'000'000;

  // Creates `path`; null plus one sentence in `error` when it cannot be created.
  // `sources`: by source id; none or one is one lidar (topics as ever), several are named apart.
  static std::unique_ptr<McapRecordingExport> create(const std::string& path, const McapExportOptions& options,
                                                     std::string& error, std::vector<SourceInfo> sources = {});
  // Writes into `sink`, which must outlive the export (tests and fuzzing use a memory sink).
  McapRecordingExport(McapSink& sink, const McapExportOptions& options, std::vector<SourceInfo> sources = {});

  // One record as a .ydrec holds it: link bytes (either direction) or a metadata payload
  // (key=value text). Records of unknown types, or of a source the export was not made with, are
  // ignored, as readers of .ydrec skip what they do not know.
  void record(RecordType type, std::span<const std::uint8_t> payload, std::int64_t t_ns, std::uint16_t source = 0);
  void metadata(const RecordingMetadata& changes, std::int64_t t_ns, std::uint16_t source = 0);
  // No record of `source` came until `t_ns` (a live tap): see RosTopicEncoder::idle.
  void idle(std::int64_t t_ns, std::uint16_t source = 0);
  // A lap decoded elsewhere (the app's shown laps): its /scan and /points, stamped and timed
  // from its own receive times as RosTopicEncoder does (scan_times), logged at its closing byte.
  // `rx_to_epoch_ns` turns its receive times into ns since the Unix epoch.
  // One lidar's export only: source 0's channels.
  void lap(const Lap& lap, Model model, std::int64_t rx_to_epoch_ns);
  // Closes the open chunk so what was written so far is readable (call at least once a second live).
  bool flush();
  // Last laps and diagnostics, summary and footer. False plus error() if anything failed.
  bool finish();

  bool failed() const { return writer_.failed() || (file_ && !file_->error().empty()); }
  // The first failure: the writer's, or closing the file's.
  const std::string& error() const { return writer_.failed() || !file_ ? writer_.error() : file_->error(); }
  const McapStatistics& statistics() const { return writer_.statistics(); }
  std::uint64_t bytes_written() const { return writer_.bytes_written(); }
  RosTopicEncoder& encoder(std::size_t source = 0) { return *lanes_.at(source).encoder; }
  std::size_t source_count() const { return lanes_.size(); }
  // Also sees every message written (the bridge serves them while they are recorded).
  // `source`: 0 for one lidar, else the source id.
  using Observer =
      std::function<void(std::size_t source, RosTopic, std::uint64_t log_time, std::span<const std::uint8_t> cdr)>;
  void set_observer(Observer observer) { observer_ = std::move(observer); }

 private:
  // One source's encoder and channels.
  struct Lane {
    std::unique_ptr<RosTopicEncoder> encoder;
    std::uint16_t channel[kRosTopicCount] = {};  // 0: not in the file (link bytes left out)
    std::uint32_t sequence[kRosTopicCount] = {};
    std::string metadata_name;
    std::optional<std::uint64_t> reached;  // the log time its records have come up to
  };
  // A message not yet written; held_ is a min-heap on (log_time, order).
  struct Held {
    std::uint64_t log_time;
    std::uint64_t order;
    std::uint16_t channel;
    std::uint32_t sequence;
    std::vector<std::uint8_t> cdr;
  };
  McapRecordingExport(std::unique_ptr<McapFileSink> file, const McapExportOptions& options,
                      std::vector<SourceInfo> sources);
  void emit(Lane& lane, RosTopic topic, std::uint64_t log_time, std::span<const std::uint8_t> cdr);
  void write_tf_static();
  void hold(std::uint16_t channel, std::uint32_t sequence, std::uint64_t log_time, std::span<const std::uint8_t> cdr);
  // `lane`'s records came up to `log_time`: writes the messages that are now due.
  void reached(Lane& lane, std::uint64_t log_time);
  void write_due();
  void write_held(std::uint64_t up_to);

  std::unique_ptr<McapFileSink> file_;  // when the export owns its file
  McapWriter writer_;
  std::vector<Lane> lanes_;
  std::vector<SourceInfo> sources_;  // by source id; none or one: one lidar
  std::uint16_t tf_channel_ = 0;
  bool tf_written_ = false;
  RosFrameOptions frame_;
  std::vector<float> scan_scratch_;  // lap()'s
  std::vector<std::uint8_t> message_;
  bool finished_ = false;
  Observer observer_;
  std::vector<Held> held_;
  std::vector<std::vector<std::uint8_t>> spare_;  // held buffers to reuse
  std::uint64_t arrivals_ = 0;
};

// The channel metadata the ros2 profile requires: offered_qos_profiles as rosbag2 writes it
// (reliable, volatile), so `ros2 bag play` republishes with a matching QoS.
const McapMetadataMap& ros2_channel_metadata();
// /tf_static's: reliable, transient-local, keep-last 1 (latched, as tf2's static broadcaster
// offers it), so tf2's static listener gets the poses from `ros2 bag play` whenever it starts.
const McapMetadataMap& ros2_latched_channel_metadata();

}  // namespace ydscope
