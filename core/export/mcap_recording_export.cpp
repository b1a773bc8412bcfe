#include "core/export/mcap_recording_export.h"

#include <algorithm>
#include <string_view>

#include "core/export/ros_tf.h"

namespace ydscope {

RosExportOptions ros_options_of(const RosExportOptions& base, std::span<const SourceInfo> sources, std::size_t id) {
  RosExportOptions ros = base;
  if (id >= sources.size()) return ros;
  if (named_apart(sources)) ros.frame.frame_id = sources[id].frame();
  if (sources[id].model) ros.model = sources[id].model;
  return ros;
}

std::string source_topic_name(std::span<const SourceInfo> sources, std::size_t id, std::string_view topic) {
  return (!named_apart(sources) ? std::string() : "/" + sources[id].name) + std::string(topic);
}

namespace {

// One offered QoS profile in rosbag2's YAML (rosbag2_storage/qos.cpp, the integer enums of its
// metadata versions before 9, which every rosbag2 since Humble reads): history 1 keep-last and
// 3 unknown, reliability 1 reliable, durability 1 transient-local and 2 volatile; the durations
// are rmw's "infinite" as a recording shows it.
std::string offered_qos_yaml(int history, int depth, int durability) {
  return "- history: " + std::to_string(history) + "\n  depth: " + std::to_string(depth) +
         "\n"
         "  reliability: 1\n"
         "  durability: " +
         std::to_string(durability) +
         "\n"
         "  deadline:\n"
         "    sec: 9223372036\n"
         "    nsec: 854775807\n"
         "  lifespan:\n"
         "    sec: 9223372036\n"
         "    nsec: 854775807\n"
         "  liveliness: 1\n"
         "  liveliness_lease_duration:\n"
         "    sec: 9223372036\n"
         "    nsec: 854775807\n"
         "  avoid_ros_namespace_conventions: false";
}

}  // namespace

const McapMetadataMap& ros2_channel_metadata() {
  static const McapMetadataMap metadata{{"offered_qos_profiles", offered_qos_yaml(3, 0, 2)}};
  return metadata;
}

const McapMetadataMap& ros2_latched_channel_metadata() {
  static const McapMetadataMap metadata{{"offered_qos_profiles", offered_qos_yaml(1, 1, 1)}};
  return metadata;
}

std::unique_ptr<McapRecordingExport> McapRecordingExport::create(const std::string& path,
                                                                 const McapExportOptions& options, std::string& error,
                                                                 std::vector<SourceInfo> sources) {
  auto file = McapFileSink::create(path, error);
  if (!file) return nullptr;
  return std::unique_ptr<McapRecordingExport>(new McapRecordingExport(std::move(file), options, std::move(sources)));
}

McapRecordingExport::McapRecordingExport(std::unique_ptr<McapFileSink> file, const McapExportOptions& options,
                                         std::vector<SourceInfo> sources)
    : McapRecordingExport(*file, options, std::move(sources)) {
  file_ = std::move(file);
}

McapRecordingExport::McapRecordingExport(McapSink& sink, const McapExportOptions& options,
                                         std::vector<SourceInfo> sources)
    : writer_(sink, options.mcap), sources_(std::move(sources)), frame_(options.ros.frame) {
  std::uint16_t schema_ids[kRosTopicCount] = {};
  for (const RosTopicInfo& topic : ros_topics()) {
    const auto i = static_cast<std::size_t>(topic.topic);
    // Topics that share a type share its schema record.
    for (const RosTopicInfo& earlier : ros_topics()) {
      if (&earlier == &topic) break;
      if (earlier.schema == topic.schema) schema_ids[i] = schema_ids[static_cast<std::size_t>(earlier.topic)];
    }
    if (!schema_ids[i]) {
      const std::string_view text = topic.schema->text;
      schema_ids[i] = writer_.add_schema(topic.schema->name, "ros2msg",
                                         {reinterpret_cast<const std::uint8_t*>(text.data()), text.size()});
    }
  }
  const std::size_t count = std::max<std::size_t>(sources_.size(), 1);
  for (std::size_t id = 0; id < count; ++id) {
    Lane lane;
    lane.encoder = std::make_unique<RosTopicEncoder>(ros_options_of(options.ros, sources_, id));
    lane.metadata_name =
        std::string(kMcapRecordingMetadataName) + (!named_apart(sources_) ? "" : "." + sources_[id].name);
    for (const RosTopicInfo& topic : ros_topics()) {
      const auto i = static_cast<std::size_t>(topic.topic);
      if (!options.ros.link_bytes && is_link_bytes(topic.topic)) continue;  // not advertised at all
      lane.channel[i] = writer_.add_channel(schema_ids[i], source_topic_name(sources_, id, topic.name), "cdr",
                                            ros2_channel_metadata());
    }
    lanes_.push_back(std::move(lane));
  }
  {  // every lidar, one too: its mount in the parent frame and its unit frame (ros_tf.h)
    const RosSchema& tf = tf_message_schema();
    const std::uint16_t schema =
        writer_.add_schema(tf.name, "ros2msg", {reinterpret_cast<const std::uint8_t*>(tf.text.data()), tf.text.size()});
    // Latched, as tf2's static broadcaster offers it: a late subscriber on replay still gets it.
    tf_channel_ = writer_.add_channel(schema, "/tf_static", "cdr", ros2_latched_channel_metadata());
  }
}

void McapRecordingExport::emit(Lane& lane, RosTopic topic, std::uint64_t log_time, std::span<const std::uint8_t> cdr) {
  const auto i = static_cast<std::size_t>(topic);
  // The bridge gets it now; the file when it is due.
  if (observer_) observer_(static_cast<std::size_t>(&lane - lanes_.data()), topic, log_time, cdr);
  if (lane.channel[i]) hold(lane.channel[i], lane.sequence[i]++, log_time, cdr);
}

namespace {
bool later(const auto& a, const auto& b) {
  return a.log_time != b.log_time ? a.log_time > b.log_time : a.order > b.order;
}
}  // namespace

void McapRecordingExport::hold(std::uint16_t channel, std::uint32_t sequence, std::uint64_t log_time,
                               std::span<const std::uint8_t> cdr) {
  std::vector<std::uint8_t> buffer;
  if (!spare_.empty()) {
    buffer = std::move(spare_.back());
    spare_.pop_back();
  }
  buffer.assign(cdr.begin(), cdr.end());
  held_.push_back({log_time, arrivals_++, channel, sequence, std::move(buffer)});
  std::push_heap(held_.begin(), held_.end(), [](const Held& a, const Held& b) { return later(a, b); });
}

void McapRecordingExport::write_held(std::uint64_t up_to) {
  while (!held_.empty() && held_.front().log_time <= up_to) {
    std::pop_heap(held_.begin(), held_.end(), [](const Held& a, const Held& b) { return later(a, b); });
    Held& m = held_.back();
    writer_.write_message(m.channel, m.sequence, m.log_time, m.log_time, m.cdr);
    spare_.push_back(std::move(m.cdr));
    held_.pop_back();
  }
}

void McapRecordingExport::reached(Lane& lane, std::uint64_t log_time) {
  lane.reached = std::max(lane.reached.value_or(0), log_time);
  write_due();
}

void McapRecordingExport::write_due() {
  std::uint64_t slowest = UINT64_MAX, newest = 0;
  for (const Lane& lane : lanes_) {
    if (!lane.reached) continue;
    slowest = std::min(slowest, *lane.reached);
    newest = std::max(newest, *lane.reached);
  }
  if (newest == 0) return;
  const std::uint64_t by_all = slowest > kHoldBackNs ? slowest - kHoldBackNs : 0;
  const std::uint64_t by_newest = newest > kHoldLimitNs ? newest - kHoldLimitNs : 0;
  write_held(std::max(by_all, by_newest));
}

void McapRecordingExport::write_tf_static() {
  if (tf_written_) return;
  tf_written_ = true;
  std::vector<RosTransform> transforms;
  for (std::size_t id = 0; id < lanes_.size(); ++id) {
    const RosFrameOptions& frame = lanes_[id].encoder->frame();  // its frame_id: this lidar's frame
    append_lidar_transforms(id < sources_.size() ? sources_[id].pose : Pose{}, frame, frame_.parent_frame_id,
                            frame.frame_id, transforms);
  }
  // At the recording's start: a static transform holds from then on.
  const auto& start = lanes_.front().encoder->recording_metadata().start_wall_time;
  const std::uint64_t stamp = start ? parse_iso8601_utc_ns(*start).value_or(0) : 0;
  std::vector<std::uint8_t> cdr;
  encode_tf_message(transforms, stamp, cdr);
  hold(tf_channel_, 0, stamp, cdr);
}

void McapRecordingExport::record(RecordType type, std::span<const std::uint8_t> payload, std::int64_t t_ns,
                                 std::uint16_t source) {
  if (source >= lanes_.size()) return;
  if (type == RecordType::Metadata)
    return metadata(RecordingMetadata::parse({reinterpret_cast<const char*>(payload.data()), payload.size()}), t_ns,
                    source);
  write_tf_static();  // every source's metadata came first: the start time is known
  Lane& lane = lanes_[source];
  lane.encoder->record(type, payload, t_ns,
                       [&](RosTopic topic, std::uint64_t log_time, std::span<const std::uint8_t> cdr) {
                         emit(lane, topic, log_time, cdr);
                       });
  reached(lane, lane.encoder->log_time(t_ns));
}

void McapRecordingExport::idle(std::int64_t t_ns, std::uint16_t source) {
  if (source >= lanes_.size()) return;
  Lane& lane = lanes_[source];
  lane.encoder->idle(t_ns, [&](RosTopic topic, std::uint64_t log_time, std::span<const std::uint8_t> cdr) {
    emit(lane, topic, log_time, cdr);
  });
  reached(lane, lane.encoder->log_time(t_ns));  // its time passes even when nothing is sent
}

void McapRecordingExport::metadata(const RecordingMetadata& changes, std::int64_t, std::uint16_t source) {
  if (source >= lanes_.size()) return;
  Lane& lane = lanes_[source];
  lane.encoder->metadata(changes);
  McapMetadataMap merged;
  const std::string text = lane.encoder->recording_metadata().encode();
  // Keys and values exactly as the .ydrec metadata payload spells them (escapes kept).
  std::string_view rest = text;
  while (!rest.empty()) {
    const std::size_t newline = rest.find('\n');
    const std::string_view line = rest.substr(0, newline);
    rest = newline == std::string_view::npos ? std::string_view{} : rest.substr(newline + 1);
    const std::size_t equals = line.find('=');
    if (equals != std::string_view::npos)
      merged[std::string(line.substr(0, equals))] = std::string(line.substr(equals + 1));
  }
  writer_.write_metadata(lane.metadata_name, merged);
}

void McapRecordingExport::lap(const Lap& lap, Model model, std::int64_t rx_to_epoch_ns) {
  const ScanTimes times = scan_times(lap, rx_to_epoch_ns);
  const auto logged = static_cast<std::uint64_t>(std::max<std::int64_t>(0, lap.last_rx_ns + rx_to_epoch_ns));
  encode_laser_scan(lap, frame_, range_limits(model), times, scan_scratch_, message_);
  emit(lanes_.front(), RosTopic::Scan, logged, message_);
  encode_point_cloud(lap, frame_, profile_for(model).flag_bits > 0, times.stamp_ns, message_);
  emit(lanes_.front(), RosTopic::Points, logged, message_);
  reached(lanes_.front(), logged);
}

bool McapRecordingExport::flush() {
  write_due();
  return writer_.flush_chunk();
}

bool McapRecordingExport::finish() {
  if (!finished_) {
    finished_ = true;
    write_tf_static();
    for (Lane& lane : lanes_)
      lane.encoder->finish([&](RosTopic topic, std::uint64_t log_time, std::span<const std::uint8_t> cdr) {
        emit(lane, topic, log_time, cdr);
      });
    write_held(UINT64_MAX);
  }
  const bool written = writer_.close();
  const bool closed = !file_ || file_->close();
  return written && closed;
}

}  // namespace ydscope
