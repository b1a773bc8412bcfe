// /diagnostics' level and words come from one judgement of the lidar's state now: the words name
// what set the level, and an outage is the only thing said while it lasts.
#include "core/export/lidar_condition.h"

#include <gtest/gtest.h>

namespace ydscope {
namespace {

TEST(LidarCondition, AHealthyLidarIsOkAndSaysNothingElse) {
  LidarCondition healthy;
  healthy.health = "ok";
  EXPECT_EQ(judge_lidar(healthy).level, 0);
  EXPECT_EQ(judge_lidar(healthy).message, "ok; health: ok");
  EXPECT_EQ(judge_lidar(LidarCondition{}).message, "ok; health not read");
}

TEST(LidarCondition, AWarningNamesItsCauseNotTheHealthThatIsFine) {
  LidarCondition recent_errors;
  recent_errors.health = "ok";
  recent_errors.recent_checksum_errors = 3;
  const LidarVerdict verdict = judge_lidar(recent_errors);
  EXPECT_EQ(verdict.level, 1);
  EXPECT_EQ(verdict.message, "3 checksum errors in the last 5.0 s");
}

TEST(LidarCondition, ErrorsComeFirstThenWarnings) {
  LidarCondition both;
  both.health = "error (code 0x0012)";
  both.recent_crc_mismatches = 2;
  both.no_recent_lap = true;
  const LidarVerdict verdict = judge_lidar(both);
  EXPECT_EQ(verdict.level, 2);
  EXPECT_EQ(verdict.message,
            "health: error (code 0x0012); 2 CRC8 mismatches in the last 5.0 s; no complete lap in the last second");
}

TEST(LidarCondition, AnOutageIsAnErrorAndTheOnlyThingSaid) {
  LidarCondition down;
  down.health = "ok";
  down.recent_checksum_errors = 1;
  down.link_fault = "reconnecting to /dev/ttyUSB0: /dev/ttyUSB0 was unplugged";
  down.quiet_ns = 5'200'000'000;
  EXPECT_EQ(judge_lidar(down).level, 2);
  EXPECT_EQ(judge_lidar(down).message, "no data for 5.2 s; reconnecting to /dev/ttyUSB0: /dev/ttyUSB0 was unplugged");
  down.quiet_ns.reset();
  EXPECT_EQ(judge_lidar(down).message, "no data yet; reconnecting to /dev/ttyUSB0: /dev/ttyUSB0 was unplugged");
}

}  // namespace
}  // namespace ydscope
