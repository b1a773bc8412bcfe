#include "core/export/mcap_recording_export.h"

#include <string_view>

namespace ydscope {

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

std::unique_ptr<McapRecordingExport> McapRecordingExport::create(const std::string& path, const McapExportOptions& options,
                                                                 std::string& error) {
  auto file = McapFileSink::create(path, error);
  if (!file) return nullptr;
  return std::unique_ptr<McapRecordingExport>(new McapRecordingExport(std::move(file), options));
}

McapRecordingExport::McapRecordingExport(std::unique_ptr<McapFileSink> file, const McapExportOptions& options)
    : McapRecordingExport(*file, options) {
  file_ = std::move(file);
}

McapRecordingExport::McapRecordingExport(McapSink& sink, const McapExportOptions& options)
    : writer_(sink, options.mcap), encoder_(options.ros), frame_(options.ros.frame) {
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
    channel_[i] = writer_.add_channel(schema_ids[i], topic.name, "cdr", ros2_channel_metadata());
  }
}

void McapRecordingExport::emit(RosTopic topic, std::uint64_t log_time, std::span<const std::uint8_t> cdr) {
  const auto i = static_cast<std::size_t>(topic);
  if (observer_) observer_(topic, log_time, cdr);
  writer_.write_message(channel_[i], sequence_[i]++, log_time, log_time, cdr);
}

void McapRecordingExport::record(RecordType type, std::span<const std::uint8_t> payload, std::int64_t t_ns) {
  if (type == RecordType::Metadata)
    return metadata(RecordingMetadata::parse({reinterpret_cast<const char*>(payload.data()), payload.size()}), t_ns);
  encoder_.record(type, payload, t_ns, [this](RosTopic topic, std::uint64_t log_time, std::span<const std::uint8_t> cdr) {
    emit(topic, log_time, cdr);
  });
}

void McapRecordingExport::metadata(const RecordingMetadata& changes, std::int64_t) {
  encoder_.metadata(changes);
  McapMetadataMap merged;
  const std::string text = encoder_.recording_metadata().encode();
  // Keys and values exactly as the .ydrec metadata payload spells them (escapes kept).
  std::string_view rest = text;
  while (!rest.empty()) {
    const std::size_t newline = rest.find('\n');
    const std::string_view line = rest.substr(0, newline);
    rest = newline == std::string_view::npos ? std::string_view{} : rest.substr(newline + 1);
    const std::size_t equals = line.find('=');
    if (equals != std::string_view::npos) merged[std::string(line.substr(0, equals))] = std::string(line.substr(equals + 1));
  }
  writer_.write_metadata(kMcapRecordingMetadataName, merged);
}

void McapRecordingExport::lap(const Lap& lap, Model model, std::uint64_t stamp_ns, double scan_time_s) {
  encode_laser_scan(lap, frame_, range_limits(model), stamp_ns, scan_time_s, scan_scratch_, message_);
  emit(RosTopic::Scan, stamp_ns, message_);
  encode_point_cloud(lap, frame_, stamp_ns, message_);
  emit(RosTopic::Points, stamp_ns, message_);
}

bool McapRecordingExport::flush() { return writer_.flush_chunk(); }

bool McapRecordingExport::finish() {
  if (!finished_) {
    finished_ = true;
    encoder_.finish([this](RosTopic topic, std::uint64_t log_time, std::span<const std::uint8_t> cdr) {
      emit(topic, log_time, cdr);
    });
  }
  const bool written = writer_.close();
  const bool closed = !file_ || file_->close();
  return written && closed;
}

}  // namespace ydscope
