// /diagnostics while the lidar spins up or a command is in flight: a warning that says which,
// read from the host bytes every recording and live tap holds, and OK again once a lap closes.
#include "core/export/command_watch.h"

#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "core/export/lidar_condition.h"
#include "core/export/ros_topic_encoder.h"
#include "core/sim/virtual_lidar.h"
#include "export/diagnostics_reader.h"

namespace ydscope {
namespace {

using Bytes = std::vector<std::uint8_t>;

TEST(CommandWatch, ACommandIsInFlightUntilALapClosesEvenSplitAcrossRecords) {
  CommandWatch watch;
  EXPECT_FALSE(watch.settling(0));
  watch.host_bytes(Bytes{0xA5}, 100);
  watch.host_bytes(Bytes{0x90}, 200);
  EXPECT_EQ(watch.settling(300), "command in progress: device info (A5 90)");
  watch.host_bytes(Bytes{0xA5, 0x60}, 400);
  EXPECT_EQ(watch.settling(500), "spinning up (scan command sent, no lap yet)");
  watch.lap_closed(550);
  EXPECT_FALSE(watch.settling(600));
  // A5 60 while laps still come is the session's keep-alive, not a spin-up; later it is one.
  watch.host_bytes(Bytes{0xA5, 0x60}, 700);
  EXPECT_FALSE(watch.settling(800));
  watch.host_bytes(Bytes{0xA5, 0x60}, 550 + kKeepAliveLapNs + 1);
  EXPECT_TRUE(watch.settling(550 + kKeepAliveLapNs + 2));
}

TEST(CommandWatch, StrayBytesAreNoCommandAndAStuckOneStopsBeingRoutine) {
  CommandWatch watch;
  watch.host_bytes(Bytes{0x00, 0xA5, 0x33, 0x60, 0xA5}, 0);  // A5 33 is no command; 60 alone neither
  EXPECT_FALSE(watch.settling(1));
  watch.host_bytes(Bytes{0x65}, 10);  // completes the A5 above: stop
  EXPECT_EQ(watch.settling(20), "command in progress: stop (A5 65)");
  EXPECT_TRUE(watch.settling(10 + kSettleLimitNs));
  EXPECT_FALSE(watch.settling(11 + kSettleLimitNs));
}

TEST(CommandWatch, SettlingIsAWarningInPlaceOfNoCompleteLap) {
  LidarCondition c;
  c.health = "ok";
  c.no_recent_lap = true;
  c.settling = "spinning up (scan command sent, no lap yet)";
  const LidarVerdict verdict = judge_lidar(c);
  EXPECT_EQ(verdict.level, 1);
  EXPECT_EQ(verdict.message, "spinning up (scan command sent, no lap yet)");
  c.health = "error (code 0x0012)";  // an error still outranks it
  EXPECT_EQ(judge_lidar(c).level, 2);
}

// The encoder every MCAP file and the bridge use: a virtual G6 told A5 60 warns until its laps
// come, is OK while they come, and warns again when stopped.
TEST(CommandWatch, TheDiagnosticsWriterWarnsWhileSpinningUpThenSaysOk) {
  VirtualLidarConfig config;
  config.model = Model::G6;
  config.scene = "room";
  VirtualLidar lidar(config, 0);
  RosTopicEncoder encoder({});
  RecordingMetadata metadata;
  metadata.model = "G6";
  metadata.conventions = std::string(lidar.conventions().id);
  metadata.start_wall_time = "2026-12-01T20:00:00Z";
  metadata.extra["health"] = "ok";
  encoder.metadata(metadata);
  std::vector<test::DiagnosticSeen> seen;
  const auto collect = [&](RosTopic topic, std::uint64_t, std::span<const std::uint8_t> cdr) {
    if (topic == RosTopic::Diagnostics) seen.push_back(test::diagnostic_status({cdr.begin(), cdr.end()}));
  };
  const Bytes scan{0xA5, 0x60};
  lidar.receive(scan, 0);
  encoder.host_bytes(scan, 0, collect);
  ASSERT_EQ(seen.size(), 1u);
  EXPECT_EQ(seen[0].level, 1);
  EXPECT_EQ(seen[0].message, "spinning up (scan command sent, no lap yet)");
  Bytes bytes;
  for (std::int64_t now = 1'000'000; now <= 3'000'000'000; now += 1'000'000) {
    bytes.clear();
    lidar.produce(now, bytes);
    if (!bytes.empty()) encoder.device_bytes(bytes, now, collect);
  }
  ASSERT_GE(seen.size(), 3u);
  EXPECT_EQ(seen.back().level, 0) << seen.back().message;
  EXPECT_EQ(seen.back().message, "ok; health: ok");
  const Bytes stop{0xA5, 0x65};
  encoder.host_bytes(stop, 3'000'000'001, collect);
  EXPECT_EQ(encoder.diagnostics().level, 1);
  EXPECT_EQ(encoder.diagnostics().message, "command in progress: stop (A5 65)");
}

}  // namespace
}  // namespace ydscope
