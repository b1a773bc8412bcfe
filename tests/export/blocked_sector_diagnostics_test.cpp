// /diagnostics says a blocked sector: the virtual lidar blocks 40°–75°, its bytes go through the
// same encoder the MCAP files and the bridge use, and the report warns with the sentence the app
// and `check` use, angles within a few degrees; the same lidar unblocked stays OK.
#include <gtest/gtest.h>

#include <cstdio>
#include <string>
#include <vector>

#include "core/export/ros_topic_encoder.h"
#include "core/sim/virtual_lidar.h"

namespace ydscope {
namespace {

// Five simulated seconds of a G6 in the room scene, read a millisecond at a time into the encoder.
DiagnosticReport report_after_scanning(const FaultConfig& faults) {
  VirtualLidarConfig config;
  config.model = Model::G6;
  config.scene = "room";
  config.faults = faults;
  VirtualLidar lidar(config, 0);
  RosTopicEncoder encoder({});
  RecordingMetadata metadata;
  metadata.model = "G6";
  metadata.conventions = std::string(lidar.conventions().id);
  metadata.start_wall_time = "2026-12-01T20:00:00Z";
  encoder.metadata(metadata);
  const auto ignore = [](RosTopic, std::uint64_t, std::span<const std::uint8_t>) {};
  const std::uint8_t scan[] = {0xA5, 0x60};
  lidar.receive(scan, 0);
  encoder.host_bytes(scan, 0, ignore);
  std::vector<std::uint8_t> bytes;
  for (std::int64_t now = 1'000'000; now <= 5'000'000'000; now += 1'000'000) {
    bytes.clear();
    lidar.produce(now, bytes);
    if (!bytes.empty()) encoder.device_bytes(bytes, now, ignore);
  }
  return encoder.diagnostics();
}

std::string value_of(const DiagnosticReport& report, const std::string& key) {
  for (const auto& [k, v] : report.values)
    if (k == key) return v;
  return "<none>";
}

TEST(BlockedSectorDiagnostics, WarnsWithTheSectorItsAnglesAndHowLong) {
  FaultConfig faults;
  faults.blocked_from_deg = 40;
  faults.blocked_width_deg = 35;
  const DiagnosticReport report = report_after_scanning(faults);
  EXPECT_EQ(report.level, 1) << report.message;
  const auto at = report.message.find("blocked ");
  ASSERT_NE(at, std::string::npos) << report.message;
  int from = -1, to = -1;
  double seconds = -1;
  ASSERT_EQ(std::sscanf(report.message.c_str() + at, "blocked %d°–%d° for %lf s", &from, &to, &seconds), 3)
      << report.message;
  EXPECT_NEAR(from, 40, 3) << report.message;
  EXPECT_NEAR(to, 75, 3) << report.message;
  EXPECT_GE(seconds, 4.0) << report.message;
  EXPECT_EQ(value_of(report, "blocked_sectors"), report.message.substr(at)) << report.message;
}

TEST(BlockedSectorDiagnostics, TheSameLidarUnblockedIsOk) {
  const DiagnosticReport report = report_after_scanning({});
  EXPECT_EQ(report.level, 0) << report.message;
  EXPECT_EQ(value_of(report, "blocked_sectors"), "none");
}

}  // namespace
}  // namespace ydscope
