// Sector statistics on the room scene, whose geometry is known: the bottom wall is a flat matte
// surface 2400 mm from the lidar, square to 270 degrees, with range noise of 4 mm + 0.2 % of the
// range (core/sim/scene_room.cpp). What the statistics find must agree with that within the
// protocol's range resolution and the scene's noise.
#include <gtest/gtest.h>

#include <cmath>

#include "analysis/virtual_laps.h"
#include "core/analysis/sector_statistics.h"

namespace ydscope {
namespace {

using namespace test;

constexpr double kWallMm = 2400.0;

double scene_sigma_mm(double range_mm) { return 4.0 + 0.002 * range_mm; }

SectorStatistics wall_statistics(const std::vector<Lap>& laps) {
  std::string error;
  SectorAccumulator sector(*parse_sector("260:280", error));
  for (const Lap& lap : laps) sector.add(lap);
  return sector.statistics();
}

class WallOnEveryModel : public ::testing::TestWithParam<Model> {};

TEST_P(WallOnEveryModel, MeanAndSpreadMatchTheScene) {
  const Model model = GetParam();
  const VirtualRun run = scan_virtual_lidar(model, 2.0);
  ASSERT_GE(run.laps.size(), 10u);
  const SectorStatistics s = wall_statistics(run.laps);
  EXPECT_EQ(s.laps, run.laps.size());
  ASSERT_GT(s.valid, 500u);
  EXPECT_EQ(s.valid, s.points) << "a matte wall returns every sample";
  EXPECT_DOUBLE_EQ(s.valid_share, 1.0);

  // The flat distance is the wall's for every point; the raw range grows to 2400 / cos(10 deg).
  const double resolution = run.distance_scale;  // mm per count (G1 1, G6 0.5, TG 1 as real units write)
  const double sigma = scene_sigma_mm(kWallMm);
  const double n = static_cast<double>(s.valid);
  EXPECT_NEAR(s.flat_distance_mm.mean, kWallMm, 4.0 * sigma / std::sqrt(n) + resolution);
  EXPECT_NEAR(s.flat_distance_mm.median, kWallMm, 6.0 * sigma / std::sqrt(n) + resolution);
  const double expected_spread = std::sqrt(sigma * sigma + resolution * resolution / 12.0);
  EXPECT_NEAR(s.flat_distance_mm.stddev, expected_spread, 0.12 * expected_spread);
  EXPECT_GE(s.range_mm.min, kWallMm - 4.0 * sigma);
  EXPECT_LE(s.range_mm.max, kWallMm / std::cos(10.0 * M_PI / 180.0) + 4.0 * sigma);
  EXPECT_GT(s.range_mm.stddev, s.flat_distance_mm.stddev) << "the raw range also spreads with the angle";

  std::uint64_t in_histogram = 0;
  for (const auto c : s.histogram.counts) in_histogram += c;
  EXPECT_EQ(in_histogram, s.valid);
  EXPECT_DOUBLE_EQ(s.histogram.lo, s.range_mm.min);
  EXPECT_DOUBLE_EQ(s.histogram.hi, s.range_mm.max);
  ASSERT_EQ(s.valid_share_by_angle.size(), 20u);
  EXPECT_DOUBLE_EQ(s.angle_bin_deg, 1.0);
  for (const double share : s.valid_share_by_angle) EXPECT_DOUBLE_EQ(share, 1.0);
}

INSTANTIATE_TEST_SUITE_P(Models, WallOnEveryModel, ::testing::Values(Model::G1, Model::G6, Model::TG30),
                         [](const auto& model) { return std::string(profile_for(model.param).name); });

TEST(SectorStatistics, ARangeBandPicksThePillarOutOfTheWallBehindIt) {
  // The pillar: a 250 mm radius column centred 4162 mm away at 35.2 degrees, the right wall ~5.9 m
  // behind it.
  const VirtualRun run = scan_virtual_lidar(Model::G6, 1.0);
  std::string error;
  Sector wide = *parse_sector("28:42", error);
  SectorAccumulator everything(wide);
  wide.min_mm = 3500;
  wide.max_mm = 4500;
  SectorAccumulator pillar(wide);
  for (const Lap& lap : run.laps) {
    everything.add(lap);
    pillar.add(lap);
  }
  const SectorStatistics all = everything.statistics();
  const SectorStatistics banded = pillar.statistics();
  EXPECT_GT(all.range_mm.max, 5000.0);
  EXPECT_LT(banded.points, all.points);
  EXPECT_GE(banded.range_mm.min, 3500.0);
  EXPECT_LE(banded.range_mm.max, 4500.0);
  // Nearest face 4162 - 250 = 3912 mm; the flanks curve away from there.
  EXPECT_NEAR(banded.range_mm.min, 3912.0, 4.0 * scene_sigma_mm(3912.0));
  // Bins outside the pillar's 6.9 degrees hold only background, which the band leaves out.
  EXPECT_LT(banded.valid_share_by_angle.front(), 0.0);
  EXPECT_LT(banded.valid_share_by_angle.back(), 0.0);
}

TEST(SectorStatistics, TheMirrorIsValidOnG6ButFlaggedSpecularOnG1) {
  // Right wall: mirror for angles below 4.8 degrees, matte above. G1 flags the mirror ghosts as
  // specular (flag 2); G6 has no flags, so its ghosts look like returns.
  std::string error;
  const Sector s = *parse_sector("350:10", error);
  SectorAccumulator g1(s), g6(s);
  for (const Lap& lap : scan_virtual_lidar(Model::G1, 1.0).laps) g1.add(lap);
  for (const Lap& lap : scan_virtual_lidar(Model::G6, 1.0).laps) g6.add(lap);
  const SectorStatistics a = g1.statistics(), b = g6.statistics();
  EXPECT_NEAR(a.valid_share, (10.0 - 4.8) / 20.0, 0.05);
  EXPECT_GT(b.valid_share, 0.97);
  for (std::size_t bin = 0; bin < 14; ++bin) EXPECT_DOUBLE_EQ(a.valid_share_by_angle[bin], 0.0) << bin;  // 350..4
  for (std::size_t bin = 16; bin < 20; ++bin) EXPECT_GT(a.valid_share_by_angle[bin], 0.9) << bin;        // 6..10
}

TEST(SectorStatistics, ClearStartsOverForTheNextLap) {
  const VirtualRun run = scan_virtual_lidar(Model::G6, 0.5);
  ASSERT_GE(run.laps.size(), 2u);
  std::string error;
  SectorAccumulator sector(*parse_sector("260:280", error));
  sector.add(run.laps[0]);
  const auto one = sector.statistics().points;
  sector.add(run.laps[1]);
  EXPECT_GT(sector.statistics().points, one);
  sector.clear();
  EXPECT_EQ(sector.statistics().points, 0u);
  sector.add(run.laps[1]);
  EXPECT_EQ(sector.statistics().laps, 1u);
  EXPECT_NEAR(static_cast<double>(sector.statistics().points), static_cast<double>(one), 2.0);
}

}  // namespace
}  // namespace ydscope
