// Several lidars in ROS terms: an export of two sources, each under its name, with /tf_static.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <map>
#include <numbers>
#include <vector>

#include "core/export/mcap_recording_export.h"
#include "core/export/ros_tf.h"
#include "core/protocol/scan_packet.h"
#include "export/cdr_test_reader.h"
#include "export/diagnostics_reader.h"
#include "export/mcap_test_reader.h"

namespace ydscope {
namespace {

// Two G6 laps' worth of bytes.
std::vector<std::uint8_t> g6_bytes() {
  std::vector<std::uint8_t> out;
  for (int lap = 0; lap < 3; ++lap) {
    append_scan_packet({kCtLapStart, encode_raw_angle(0), encode_raw_angle(0), std::vector<std::uint16_t>{0}}, out);
    for (int i = 0; i < 12; ++i)
      append_scan_packet({0, encode_raw_angle(i * 30.0 + 0.2), encode_raw_angle(i * 30.0 + 29.8),
                          std::vector<std::uint16_t>(20, static_cast<std::uint16_t>(4000 + 40 * lap))},
                         out);
  }
  return out;
}

TEST(McapRecordingExport, SeveralSourcesEachUnderItsNameWithTfStatic) {
  McapMemorySink sink;
  McapRecordingExport exporter(sink, {},
                               {{"front", {0.2, 0, 0, false}, Model::G6}, {"back", {-0.2, 0, 180, true}, {}}});
  for (std::uint16_t source = 0; source < 2; ++source) {
    RecordingMetadata metadata;
    metadata.model = "G6";
    metadata.start_wall_time = "2026-12-02T09:00:00Z";
    exporter.metadata(metadata, 0, source);
  }
  const auto bytes = g6_bytes();
  exporter.record(RecordType::DeviceToHost, bytes, 1000, 0);
  exporter.record(RecordType::DeviceToHost, bytes, 2000, 1);
  exporter.record(RecordType::DeviceToHost, bytes, 3000, 7);  // a source it was not made with: ignored
  ASSERT_TRUE(exporter.finish()) << exporter.error();

  const auto contents = test::read_mcap(sink.bytes());
  ASSERT_TRUE(contents.complete);
  std::map<std::string, std::uint16_t> ids;
  for (const auto& [id, channel] : contents.channels) ids[channel.topic] = id;
  for (const char* topic : {"/front/scan", "/front/points", "/front/diagnostics", "/front/ydscope/device_bytes",
                            "/back/scan", "/back/points", "/back/ydscope/host_bytes", "/tf_static"})
    EXPECT_EQ(ids.count(topic), 1u) << topic;
  EXPECT_EQ(ids.count("/scan"), 0u);
  EXPECT_EQ(contents.schemas.at(contents.channels.at(ids["/tf_static"]).schema_id).name, "tf2_msgs/msg/TFMessage");

  std::map<std::string, std::size_t> messages;
  for (const auto& m : contents.messages) {
    const std::string& topic = contents.channels.at(m.channel_id).topic;
    ++messages[topic];
    if (topic == "/front/points" || topic == "/back/points") {
      test::CdrReader r(m.data);
      r.i32();
      r.u32();
      EXPECT_EQ(r.str(), topic.substr(1, topic.find('/', 1) - 1));  // frame_id: the source's name
    }
    if (topic != "/tf_static") continue;
    EXPECT_EQ(m.log_time, 1'796'202'000'000'000'000ull);  // the recording's start
    test::CdrReader r(m.data);
    ASSERT_EQ(r.u32(), 4u);  // each lidar's mount in base_link, then its unit frame
    for (const char* child : {"front", "back"}) {
      std::vector<RosTransform> expected;
      append_lidar_transforms(std::string(child) == "front" ? Pose{0.2, 0, 0, false} : Pose{-0.2, 0, 180, true}, {},
                              "base_link", child, expected);
      for (const RosTransform& t : expected) {
        r.i32();
        r.u32();
        EXPECT_EQ(r.str(), t.parent_frame);
        EXPECT_EQ(r.str(), t.child_frame);
        double v[7];
        for (double& x : v) std::memcpy(&x, r.take(8, 8), 8);
        for (int i = 0; i < 3; ++i) EXPECT_DOUBLE_EQ(v[i], t.translation[i]);
        for (int i = 0; i < 4; ++i) EXPECT_DOUBLE_EQ(v[3 + i], t.rotation[i]);
      }
    }
    EXPECT_TRUE(r.at_end());
  }
  EXPECT_EQ(messages["/tf_static"], 1u);
  EXPECT_EQ(messages["/front/points"], 2u);
  EXPECT_EQ(messages["/back/points"], 2u);
  EXPECT_EQ(exporter.encoder(0).laps(), 2u);
  EXPECT_EQ(exporter.encoder(1).laps(), 2u);
  EXPECT_EQ(contents.metadata.size(), 2u);  // one per source's metadata record
}

// One offered QoS profile exactly as rosbag2 writes it into a channel's offered_qos_profiles
// (rosbag2_storage/src/rosbag2_storage/qos.cpp, integer enums: history 1 keep-last, 3 unknown;
// reliability 1 reliable; durability 1 transient-local, 2 volatile).
std::string rosbag2_qos(int history, int depth, int durability) {
  return "- history: " + std::to_string(history) + "\n  depth: " + std::to_string(depth) +
         "\n  reliability: 1\n  durability: " + std::to_string(durability) +
         "\n  deadline:\n    sec: 9223372036\n    nsec: 854775807\n  lifespan:\n    sec: 9223372036\n"
         "    nsec: 854775807\n  liveliness: 1\n  liveliness_lease_duration:\n    sec: 9223372036\n"
         "    nsec: 854775807\n  avoid_ros_namespace_conventions: false";
}

TEST(McapRecordingExport, TfStaticIsOfferedTransientLocalAsRosbag2WritesALatchedTopic) {
  McapMemorySink sink;
  McapRecordingExport exporter(sink, {}, {{"front", {0.2, 0, 0, false}, Model::G6}, {"back", {}, Model::G6}});
  ASSERT_TRUE(exporter.finish()) << exporter.error();
  const auto contents = test::read_mcap(sink.bytes());
  ASSERT_TRUE(contents.complete);
  std::size_t checked = 0;
  for (const auto& [id, channel] : contents.channels) {
    SCOPED_TRACE(channel.topic);
    ASSERT_EQ(channel.metadata.count("offered_qos_profiles"), 1u);
    const std::string& qos = channel.metadata.at("offered_qos_profiles");
    // tf2's static listener subscribes transient-local: only a latched offer reaches it on replay.
    EXPECT_EQ(qos, channel.topic == "/tf_static" ? rosbag2_qos(1, 1, 1) : rosbag2_qos(3, 0, 2));
    ++checked;
  }
  EXPECT_EQ(checked, 2 * kRosTopicCount + 1);
}

TEST(McapRecordingExport, WithoutLinkBytesNoLinkByteChannelIsAdvertised) {
  for (const bool several : {false, true}) {
    SCOPED_TRACE(several ? "two lidars" : "one lidar");
    McapExportOptions options;
    options.ros.link_bytes = false;
    McapMemorySink sink;
    std::vector<SourceInfo> sources;
    if (several) sources = {{"front", {}, Model::G6}, {"back", {}, Model::G6}};
    McapRecordingExport exporter(sink, options, sources);
    RecordingMetadata metadata;
    metadata.model = "G6";
    metadata.start_wall_time = "2026-12-02T09:00:00Z";
    for (std::uint16_t source = 0; source < (several ? 2 : 1); ++source) {
      exporter.metadata(metadata, 0, source);
      exporter.record(RecordType::DeviceToHost, g6_bytes(), 1000, source);
      exporter.record(RecordType::HostToDevice, std::vector<std::uint8_t>{0xA5, 0x65}, 2000, source);
    }
    ASSERT_TRUE(exporter.finish()) << exporter.error();
    const auto contents = test::read_mcap(sink.bytes());
    ASSERT_TRUE(contents.complete);
    std::size_t scans = 0;
    for (const auto& [id, channel] : contents.channels) {
      EXPECT_EQ(channel.topic.find("/ydscope/"), std::string::npos) << channel.topic << " is advertised";
      if (channel.topic.ends_with("/scan")) ++scans;
    }
    EXPECT_EQ(scans, several ? 2u : 1u);
    for (const auto& m : contents.messages)
      EXPECT_EQ(contents.channels.at(m.channel_id).topic.find("/ydscope/"), std::string::npos);
  }
}

// G6 packets one by one: `laps` laps of 12 packets after a lap start each.
std::vector<std::vector<std::uint8_t>> g6_packets(int laps) {
  std::vector<std::vector<std::uint8_t>> out;
  for (int lap = 0; lap < laps; ++lap) {
    out.emplace_back();
    append_scan_packet({kCtLapStart, encode_raw_angle(0), encode_raw_angle(0), std::vector<std::uint16_t>{0}},
                       out.back());
    for (int i = 0; i < 12; ++i) {
      out.emplace_back();
      append_scan_packet({0, encode_raw_angle(i * 30.0 + 0.2), encode_raw_angle(i * 30.0 + 29.8),
                          std::vector<std::uint16_t>(20, static_cast<std::uint16_t>(4000 + 10 * lap))},
                         out.back());
    }
  }
  return out;
}

// Two live lidars reach the export in turns (each tap's records as they were taken), and a lap
// is logged at its closing byte, after the bytes that came since: the file still holds every
// message in log-time order, as a reader streaming it expects.
TEST(McapRecordingExport, TwoLidarsArrivingInTurnsAreWrittenInLogTimeOrder) {
  McapMemorySink sink;
  McapRecordingExport exporter(sink, {}, {{"front", {}, Model::G6}, {"back", {}, Model::G6}});
  for (std::uint16_t source = 0; source < 2; ++source) {
    RecordingMetadata metadata;
    metadata.model = "G6";
    metadata.port = source == 0 ? "/dev/ttyUSB0" : "/dev/ttyUSB1";
    metadata.start_wall_time = "2026-12-02T09:00:00Z";
    exporter.metadata(metadata, 0, source);
  }
  const auto packets = g6_packets(40);
  constexpr std::int64_t kPacketNs = 10'000'000;  // 13 packets a lap: about 7.7 Hz
  constexpr std::size_t kTurn = 30;               // packets of one lidar taken at once: 300 ms
  for (std::size_t from = 0; from < packets.size(); from += kTurn)
    for (std::uint16_t source = 0; source < 2; ++source)
      for (std::size_t i = from; i < std::min(packets.size(), from + kTurn); ++i) {
        const std::int64_t t = static_cast<std::int64_t>(i) * kPacketNs + source * 3'000'000;
        exporter.record(RecordType::DeviceToHost, packets[i], t, source);
        if (i % 13 == 5) exporter.record(RecordType::HostToDevice, std::vector<std::uint8_t>{0xA5, 0x65}, t, source);
      }
  ASSERT_TRUE(exporter.finish()) << exporter.error();

  const auto contents = test::read_mcap(sink.bytes());
  ASSERT_TRUE(contents.complete);
  std::map<std::string, std::size_t> per_topic;
  std::uint64_t previous = 0;
  std::size_t out_of_order = 0;
  for (const auto& m : contents.messages) {
    const std::string& topic = contents.channels.at(m.channel_id).topic;
    ++per_topic[topic];
    if (m.log_time < previous) ++out_of_order;
    previous = std::max(previous, m.log_time);
    if (topic.ends_with("/diagnostics")) {
      // Named by the lidar from the first report on, and keyed by its port, never by its model.
      const bool front = topic == "/front/diagnostics";
      const test::DiagnosticSeen status = test::diagnostic_status(m.data);
      EXPECT_EQ(status.name, front ? "ydscope: front" : "ydscope: back");
      EXPECT_EQ(status.hardware_id, front ? "/dev/ttyUSB0" : "/dev/ttyUSB1");
    }
  }
  EXPECT_EQ(out_of_order, 0u) << "messages written after a later one, in file order";
  EXPECT_GE(per_topic["/front/scan"], 38u);
  EXPECT_EQ(per_topic["/front/scan"], per_topic["/back/scan"]);
  EXPECT_GE(per_topic["/front/diagnostics"], 4u);
  EXPECT_EQ(per_topic["/front/ydscope/device_bytes"], packets.size());
  EXPECT_EQ(per_topic["/back/ydscope/host_bytes"], 40u);
  EXPECT_EQ(contents.stat_messages, contents.messages.size());
}

}  // namespace
}  // namespace ydscope
