#pragma once
// RosTopicEncoder: the records of a recording (.ydrec on disk, or the live session's record tap)
// in, ROS 2 messages out, for any sink (an MCAP file, the WebSocket bridge). It decodes the
// device->host bytes itself with the same ScanDecoder that `ydscope-cli decode` uses, so /scan
// and /points carry exactly what decode prints for the same bytes.
//
// Topics: /scan (sensor_msgs/msg/LaserScan), /points (sensor_msgs/msg/PointCloud2),
// /diagnostics (diagnostic_msgs/msg/DiagnosticArray, once per second of recorded time, its level
// from the lidar's state now: core/export/lidar_condition.h; while the session's link is down,
// idle() keeps it coming, reporting the outage), and the
// link bytes with their times on /ydscope/device_bytes and /ydscope/host_bytes
// (std_msgs/msg/UInt8MultiArray), so the file can be decoded again exactly like a .ydrec.
//
// Times: a record at t_ns (since the recording started) is logged at start_wall_time + t_ns,
// in ns since the Unix epoch; a lap's /scan and /points are logged at its closing byte and
// stamped (header.stamp) at its first byte, the first ray's time (REP-117). Not thread-safe.
#include <cstdint>
#include <deque>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "core/analysis/dropout_ring.h"
#include "core/analysis/zone_watch.h"
#include "core/export/command_watch.h"
#include "core/export/ros_encoding.h"
#include "core/export/ros_schemas.h"
#include "core/protocol/function_ref.h"
#include "core/protocol/interference_filter.h"
#include "core/protocol/scan_decoder.h"
#include "core/record/recording_format.h"
#include "core/record/recording_metadata.h"

namespace ydscope {

// Zones last, so the other topics keep their channel ids.
enum class RosTopic : std::uint8_t { Scan, Points, Diagnostics, DeviceBytes, HostBytes, Zones };
inline constexpr std::size_t kRosTopicCount = 6;
inline constexpr bool is_link_bytes(RosTopic topic) {
  return topic == RosTopic::DeviceBytes || topic == RosTopic::HostBytes;
}

struct RosTopicInfo {
  RosTopic topic;
  std::string_view name;  // "/scan"
  const RosSchema* schema;
};
std::span<const RosTopicInfo> ros_topics();

struct RosExportOptions {
  RosFrameOptions frame;
  std::optional<Model> model;            // forced; otherwise the recording's model
  std::optional<double> distance_scale;  // forced; otherwise the recording's, else the conventions'
  // Forced; otherwise the conventions the recording was made with (recorded_conventions.h).
  std::optional<Reading> reading;
  InterferenceFilter filter;  // applied to /scan and /points only
  bool link_bytes = true;     // publish /ydscope/device_bytes and /ydscope/host_bytes
  // Watched lap by lap (polygons through the recording's pose): each zone's status on /zones, at
  // once on every entry or exit and with every /diagnostics, and beside the lidar's own there.
  std::vector<Zone> zones;
};

// ns since the Unix epoch of "2026-11-22T02:20:00.123Z" (fraction optional); empty if malformed.
std::optional<std::uint64_t> parse_iso8601_utc_ns(std::string_view text);

class RosTopicEncoder {
 public:
  // One encoded message; `cdr` is valid only during the call.
  using MessageFn = FunctionRef<void(RosTopic topic, std::uint64_t log_time_ns, std::span<const std::uint8_t> cdr)>;

  explicit RosTopicEncoder(RosExportOptions options);

  // One record as a .ydrec holds it (metadata payloads are key=value text); unknown types ignored.
  void record(RecordType type, std::span<const std::uint8_t> payload, std::int64_t t_ns, MessageFn emit);
  // A metadata record: merged; sets the model (unless forced) and the time base.
  void metadata(const RecordingMetadata& changes);
  void device_bytes(std::span<const std::uint8_t> bytes, std::int64_t t_ns, MessageFn emit);
  void host_bytes(std::span<const std::uint8_t> bytes, std::int64_t t_ns, MessageFn emit);
  // End of the recording: laps still held back by the decoder, and a last /diagnostics.
  void finish(MessageFn emit);
  // No record came until `t_ns` (a live tap): while the session says its link is down (metadata
  // link_fault), /diagnostics keeps its rate and reports the outage; otherwise nothing.
  void idle(std::int64_t t_ns, MessageFn emit);

  // Changes apply from the next lap (the bridge's filter parameters).
  void set_filter(InterferenceFilter filter) { options_.filter = filter; }
  const InterferenceFilter& filter() const { return options_.filter; }
  // Extra diagnostic values (e.g. the live tap's dropped records); replaced on each call.
  void set_extra_diagnostics(std::vector<std::pair<std::string, std::string>> values) { extra_ = std::move(values); }

  const RecordingMetadata& recording_metadata() const { return metadata_; }
  const RosFrameOptions& frame() const { return options_.frame; }
  // A record at `t_ns` is logged at this time (ns since the Unix epoch).
  std::uint64_t log_time(std::int64_t t_ns) const;
  // Empty before the model is known.
  std::optional<DecoderCounters> counters() const;
  std::uint64_t laps() const { return laps_; }
  // The report /diagnostics would carry now.
  DiagnosticReport diagnostics() const;

 private:
  void on_lap(const Lap& lap, MessageFn emit);
  // The decoder, once the model is known: the metadata written at the start names the
  // conventions, so it is made with the first device bytes.
  void make_decoder();
  void maybe_diagnostics(std::int64_t t_ns, MessageFn emit);
  void count_recent_errors(std::int64_t t_ns);
  void emit_zones(std::uint64_t log_time_ns, MessageFn emit);
  bool link_down() const;

  RosExportOptions options_;
  RecordingMetadata metadata_;
  std::uint64_t wall_start_ns_ = 0;
  const ModelProfile* profile_ = nullptr;
  std::unique_ptr<ScanDecoder> decoder_;
  std::int64_t last_t_ns_ = 0;
  std::int64_t next_diagnostics_ns_ = 0;
  bool seen_bytes_ = false;
  std::optional<std::int64_t> last_device_t_ns_;
  // The decoder's error counts at each report within kConditionWindowNs, and the errors since the
  // oldest: what counts against the level now.
  struct ErrorSample {
    std::int64_t t_ns;
    std::uint64_t checksum_errors;
    std::uint64_t crc_mismatches;
  };
  std::deque<ErrorSample> error_samples_;
  std::uint64_t recent_checksum_errors_ = 0;
  std::uint64_t recent_crc_mismatches_ = 0;
  std::uint64_t laps_ = 0;
  // Lap closes of the current diagnostics window, for the measured scan rate.
  std::optional<std::int64_t> window_first_close_ns_;
  std::int64_t window_last_close_ns_ = 0;
  std::uint64_t window_laps_ = 0;
  std::optional<double> measured_scan_hz_;
  std::optional<double> reported_scan_hz_;  // G1 CT
  CommandWatch commands_;                   // spinning up, a command in flight
  DropoutRing dropouts_;                    // blocked sectors, for the level and the message
  ZoneWatch zones_;
  std::vector<std::pair<std::string, std::string>> extra_;
  Lap filtered_;
  std::vector<float> scan_scratch_;
  std::vector<std::uint8_t> message_;
};

}  // namespace ydscope
