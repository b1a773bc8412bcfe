#include "core/export/mcap_recording_export.h"

#include <algorithm>
#include <string_view>

#include "core/export/ros_tf.h"

namespace ydscope {

RosExportOptions ros_options_of(const RosExportOptions& base, const McapSource& source) {
  RosExportOptions ros = base;
  ros.frame.frame_id = source.name;
  if (source.model) ros.model = source.model;
  return ros;
}

std::string source_topic_name(std::span<const McapSource> sources, std::size_t id, std::string_view topic) {
  return (sources.empty() ? std::string() : "/" + sources[id].name) + std::string(topic);
}

const McapMetadataMap& ros2_channel_metadata() {
  static const McapMetadataMap metadata{{"offered_qos_profiles",
                                         "- history: 3\n"
                                         "  depth: 0\n"
                                         "  reliability: 1\n"
                                         "  durability: 2\n"
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
                                         "  avoid_ros_namespace_conventions: false"}};
  return metadata;
}

std::unique_ptr<McapRecordingExport> McapRecordingExport::create(const std::string& path,
                                                                 const McapExportOptions& options, std::string& error,
                                                                 std::vector<McapSource> sources) {
  auto file = McapFileSink::create(path, error);
  if (!file) return nullptr;
  return std::unique_ptr<McapRecordingExport>(new McapRecordingExport(std::move(file), options, std::move(sources)));
}

McapRecordingExport::McapRecordingExport(std::unique_ptr<McapFileSink> file, const McapExportOptions& options,
                                         std::vector<McapSource> sources)
    : McapRecordingExport(*file, options, std::move(sources)) {
  file_ = std::move(file);
}

McapRecordingExport::McapRecordingExport(McapSink& sink, const McapExportOptions& options,
                                         std::vector<McapSource> sources)
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
  const std::size_t count = sources_.empty() ? 1 : sources_.size();
  for (std::size_t id = 0; id < count; ++id) {
    Lane lane;
    lane.encoder =
        std::make_unique<RosTopicEncoder>(sources_.empty() ? options.ros : ros_options_of(options.ros, sources_[id]));
    lane.metadata_name = std::string(kMcapRecordingMetadataName) + (sources_.empty() ? "" : "." + sources_[id].name);
    for (const RosTopicInfo& topic : ros_topics()) {
      const auto i = static_cast<std::size_t>(topic.topic);
      lane.channel[i] = writer_.add_channel(schema_ids[i], source_topic_name(sources_, id, topic.name), "cdr",
                                            ros2_channel_metadata());
    }
    lanes_.push_back(std::move(lane));
  }
  if (!sources_.empty()) {
    const RosSchema& tf = tf_message_schema();
    const std::uint16_t schema =
        writer_.add_schema(tf.name, "ros2msg", {reinterpret_cast<const std::uint8_t*>(tf.text.data()), tf.text.size()});
    tf_channel_ = writer_.add_channel(schema, "/tf_static", "cdr", ros2_channel_metadata());
  }
}

void McapRecordingExport::emit(Lane& lane, RosTopic topic, std::uint64_t log_time, std::span<const std::uint8_t> cdr) {
  const auto i = static_cast<std::size_t>(topic);
  if (observer_) observer_(static_cast<std::size_t>(&lane - lanes_.data()), topic, log_time, cdr);
  writer_.write_message(lane.channel[i], lane.sequence[i]++, log_time, log_time, cdr);
}

void McapRecordingExport::write_tf_static() {
  if (sources_.empty() || tf_written_) return;
  tf_written_ = true;
  std::vector<RosTransform> transforms;
  for (const McapSource& source : sources_)
    transforms.push_back(ros_transform_of(source.pose, lanes_.front().encoder->frame(), kCommonFrameId, source.name));
  // At the recording's start: a static transform holds from then on.
  const auto& start = lanes_.front().encoder->recording_metadata().start_wall_time;
  const std::uint64_t stamp = start ? parse_iso8601_utc_ns(*start).value_or(0) : 0;
  std::vector<std::uint8_t> cdr;
  encode_tf_message(transforms, stamp, cdr);
  writer_.write_message(tf_channel_, 0, stamp, stamp, cdr);
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
}

void McapRecordingExport::idle(std::int64_t t_ns, std::uint16_t source) {
  if (source >= lanes_.size()) return;
  Lane& lane = lanes_[source];
  lane.encoder->idle(t_ns, [&](RosTopic topic, std::uint64_t log_time, std::span<const std::uint8_t> cdr) {
    emit(lane, topic, log_time, cdr);
  });
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
}

bool McapRecordingExport::flush() { return writer_.flush_chunk(); }

bool McapRecordingExport::finish() {
  if (!finished_) {
    finished_ = true;
    write_tf_static();
    for (Lane& lane : lanes_)
      lane.encoder->finish([&](RosTopic topic, std::uint64_t log_time, std::span<const std::uint8_t> cdr) {
        emit(lane, topic, log_time, cdr);
      });
  }
  const bool written = writer_.close();
  const bool closed = !file_ || file_->close();
  return written && closed;
}

}  // namespace ydscope
