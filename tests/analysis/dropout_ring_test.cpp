// The dropout ring on the virtual lidar's simulated clock: a sector the virtual lidar blocks is
// found with its angles (within a few degrees, on triangulation and time-of-flight units alike)
// and how long it has been empty; the scenes as they are show no blocked sector; a lidar that sees
// nothing anywhere is not called blocked in one place.
#include <gtest/gtest.h>

#include <cmath>

#include "analysis/virtual_laps.h"
#include "core/analysis/dropout_ring.h"

namespace ydscope {
namespace {

using namespace test;

constexpr int kToleranceDeg = 3;

int angle_gap(int a, int b) {
  const int d = std::abs(a - b) % 360;
  return std::min(d, 360 - d);
}

FaultConfig blocked_from_to(double from_deg, double to_deg) {
  FaultConfig faults;
  faults.blocked_from_deg = from_deg;
  faults.blocked_width_deg = std::fmod(to_deg - from_deg + 360.0, 360.0);
  return faults;
}

DropoutRing ring_over(const VirtualRun& run) {
  DropoutRing ring;
  for (const Lap& lap : run.laps) ring.add_lap(lap);
  return ring;
}

struct BlockCase {
  Model model;
  std::string scene;
  double from_deg;
  double to_deg;
};

class BlockedSectorFound : public ::testing::TestWithParam<BlockCase> {};

TEST_P(BlockedSectorFound, WithItsAnglesAndHowLong) {
  const BlockCase& c = GetParam();
  const VirtualRun run = scan_virtual_lidar(c.model, 5.0, blocked_from_to(c.from_deg, c.to_deg), c.scene);
  ASSERT_GT(run.laps.size(), 30u);
  const DropoutRing ring = ring_over(run);
  const std::vector<BlockedSector> blocked = ring.blocked();
  ASSERT_EQ(blocked.size(), 1u) << describe_blocked_sectors(blocked);
  EXPECT_LE(angle_gap(blocked[0].from_deg, static_cast<int>(c.from_deg)), kToleranceDeg)
      << describe_blocked_sector(blocked[0]);
  EXPECT_LE(angle_gap(blocked[0].to_deg, static_cast<int>(c.to_deg)), kToleranceDeg)
      << describe_blocked_sector(blocked[0]);
  // Empty from the first lap to the last: nearly the whole run.
  const double span_s = static_cast<double>(run.laps.back().last_rx_ns - run.laps.front().last_rx_ns) * 1e-9;
  EXPECT_NEAR(blocked[0].for_s, span_s, 0.2);
  // The ring says the same per degree: full inside, far from full well outside.
  const auto share = ring.no_return_share();
  const auto mid = static_cast<std::size_t>(blocked[0].centre_deg());
  EXPECT_GE(share[mid], 0.99f);
  EXPECT_EQ(describe_blocked_sector(blocked[0]).rfind("blocked ", 0), 0u);
}

INSTANTIATE_TEST_SUITE_P(Models, BlockedSectorFound,
                         ::testing::Values(BlockCase{Model::G1, "room", 40, 75}, BlockCase{Model::G6, "room", 40, 75},
                                           BlockCase{Model::TG30, "room", 40, 75},
                                           BlockCase{Model::G6, "demo", 200, 230},
                                           BlockCase{Model::G1, "booth", 350, 15}),
                         [](const auto& test) {
                           return std::string(profile_for(test.param.model).name) + "_" + test.param.scene + "_" +
                                  std::to_string(static_cast<int>(test.param.from_deg));
                         });

struct SceneCase {
  Model model;
  std::string scene;
};

class CleanScene : public ::testing::TestWithParam<SceneCase> {};

TEST_P(CleanScene, HasNoBlockedSector) {
  const VirtualRun run = scan_virtual_lidar(GetParam().model, 5.0, {}, GetParam().scene);
  ASSERT_GT(run.laps.size(), 30u);
  const DropoutRing ring = ring_over(run);
  EXPECT_TRUE(ring.blocked().empty()) << describe_blocked_sectors(ring.blocked());
}

INSTANTIATE_TEST_SUITE_P(
    Scenes, CleanScene,
    ::testing::Values(SceneCase{Model::G1, "room"}, SceneCase{Model::G6, "room"}, SceneCase{Model::TG30, "room"},
                      SceneCase{Model::G1, "demo"}, SceneCase{Model::G6, "demo"}, SceneCase{Model::TG30, "demo"},
                      SceneCase{Model::G1, "booth"}, SceneCase{Model::G6, "booth"}, SceneCase{Model::TG30, "booth"}),
    [](const auto& test) { return std::string(profile_for(test.param.model).name) + "_" + test.param.scene; });

Lap lap_at(std::int64_t t_ns, float range_mm, float empty_from, float empty_to) {
  Lap lap;
  lap.last_rx_ns = t_ns;
  lap.angles_corrected = false;
  for (int i = 0; i < 720; ++i) {
    const float a = static_cast<float>(i) * 0.5f;
    const bool in_gap = empty_from <= empty_to ? a >= empty_from && a < empty_to : a >= empty_from || a < empty_to;
    lap.points.push_back({a, in_gap ? 0.0f : range_mm, PointFlag::None});
  }
  return lap;
}

TEST(DropoutRing, NothingAnywhereIsNotABlockage) {
  DropoutRing ring;
  for (int i = 1; i <= 30; ++i) ring.add_lap(lap_at(i * 100 * kMs, 0.0f, 0, 0));
  EXPECT_TRUE(ring.blocked().empty());
  EXPECT_FLOAT_EQ(ring.no_return_share()[100], 1.0f);
}

TEST(DropoutRing, SectorAcrossZeroComesOutWholeAndNarrowGapsAreLeftOut) {
  DropoutRing ring;
  for (int i = 1; i <= 30; ++i) {
    Lap lap = lap_at(i * 100 * kMs, 2000.0f, 350.0f, 20.0f);
    for (LapPoint& p : lap.points)
      if (p.angle_deg >= 100.0f && p.angle_deg < 102.0f) p.range_mm = 0.0f;  // a 2° post
    ring.add_lap(lap);
  }
  const auto blocked = ring.blocked();
  ASSERT_EQ(blocked.size(), 1u) << describe_blocked_sectors(blocked);
  EXPECT_EQ(blocked[0].from_deg, 350);
  EXPECT_EQ(blocked[0].to_deg, 20);
  EXPECT_EQ(blocked[0].width_deg(), 30);
  EXPECT_EQ(describe_blocked_sector(blocked[0]), "blocked 350°–20° for 3 s");
}

TEST(DropoutRing, NotJudgedBeforeASecondOfLapsAndForgetsAClearedBlockage) {
  DropoutRing ring;
  ring.add_lap(lap_at(100 * kMs, 2000.0f, 40.0f, 75.0f));
  EXPECT_TRUE(ring.blocked().empty());  // one lap is no evidence
  std::int64_t t = 100 * kMs;
  for (int i = 0; i < 20; ++i) ring.add_lap(lap_at(t += 100 * kMs, 2000.0f, 40.0f, 75.0f));
  ASSERT_EQ(ring.blocked().size(), 1u);
  // Wiped clean: once the window holds only clear laps, the sector is gone.
  for (int i = 0; i < 40; ++i) ring.add_lap(lap_at(t += 100 * kMs, 2000.0f, 0, 0));
  EXPECT_TRUE(ring.blocked().empty()) << describe_blocked_sectors(ring.blocked());
  EXPECT_FLOAT_EQ(ring.no_return_share()[50], 0.0f);
}

}  // namespace
}  // namespace ydscope
