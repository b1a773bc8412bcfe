// Lap timing on the virtual lidar's simulated clock: the rate it was set to, no jitter, the
// ranging frequency as the sample rate, and lost samples counted exactly from the packets the
// faults kept off the line.
#include <gtest/gtest.h>

#include "analysis/virtual_laps.h"
#include "core/analysis/lap_timing.h"
#include "support/field_decoder.h"

namespace ydscope {
namespace {

using namespace test;

LapTimingStatistics timing_of(const std::vector<Lap>& laps) {
  LapTimingAccumulator timing;
  for (const Lap& lap : laps) timing.add(lap);
  return timing.statistics();
}

// Samples missing from the host's laps in the device laps they cover (from the first zero packet
// that arrived to the one after the last lap's): those that never arrived (lost, stalled or broken
// packets) and those the decoder dropped after cutting a lap short. Every host lap starts at a
// zero packet that arrived, so the window is counted in the device's own laps.
std::uint64_t truly_missing(const VirtualRun& run) {
  std::vector<std::uint64_t> arrived_zero_laps;
  for (const TruthPacket& p : run.truth)
    if (p.index == 0 && !p.lost && !p.corrupted) arrived_zero_laps.push_back(p.lap);
  if (arrived_zero_laps.size() <= run.laps.size()) return 0;
  const std::uint64_t first = arrived_zero_laps.front(), end = arrived_zero_laps[run.laps.size()];
  std::uint64_t sent = 0, in_laps = 0;
  for (const TruthPacket& p : run.truth)
    if (p.lap >= first && p.lap < end) sent += p.points.size();
  for (const Lap& lap : run.laps) in_laps += lap.points.size();
  return sent - in_laps;
}

class CleanStream : public ::testing::TestWithParam<Model> {};

TEST_P(CleanStream, RateIsTheSetOneAndSamplesAreTheRangingFrequency) {
  const ModelProfile& profile = profile_for(GetParam());
  const VirtualRun run = scan_virtual_lidar(GetParam(), 3.0);
  const LapTimingStatistics t = timing_of(run.laps);
  EXPECT_EQ(t.laps, run.laps.size());
  EXPECT_EQ(t.interruptions, 0u);
  EXPECT_EQ(t.normal_laps, t.laps);
  EXPECT_NEAR(t.mean_hz, profile.default_scan_hz, 0.001 * profile.default_scan_hz);
  EXPECT_EQ(t.jitter_pct, 0.0);  // every lap holds the same samples
  EXPECT_NEAR(t.min_hz, t.max_hz, 1e-9);
  // What a real unit sends at its default ranging code (the conventions' table).
  const double samples_per_s = field_samples_per_s(GetParam());
  EXPECT_NEAR(t.sample_rate_hz, samples_per_s, 0.002 * samples_per_s);
  EXPECT_EQ(t.lost_samples, 0u);
  EXPECT_EQ(t.series.size(), t.normal_laps);
  std::uint64_t points = 0;
  for (const Lap& lap : run.laps) points += lap.points.size();
  EXPECT_EQ(t.points, points);
}

INSTANTIATE_TEST_SUITE_P(Models, CleanStream, ::testing::Values(Model::G1, Model::G6, Model::TG15),
                         [](const auto& model) { return std::string(profile_for(model.param).name); });

TEST(LapTiming, LostPacketsAreCountedSampleForSample) {
  FaultConfig faults;
  faults.lost_packet_rate = 0.02;
  const VirtualRun run = scan_virtual_lidar(Model::G6, 3.0, faults);
  ASSERT_GT(run.faults.lost_packets, 5u);
  const LapTimingStatistics t = timing_of(run.laps);
  EXPECT_EQ(t.lost_samples, truly_missing(run));
  EXPECT_EQ(t.interruptions, 0u) << "zero packets are never lost by this fault";
  const double g6_rate = field_samples_per_s(Model::G6);  // 18 k at code 2, as real G6 units
  EXPECT_NEAR(t.sample_rate_hz, g6_rate, 0.002 * g6_rate) << "lost samples still belong to the device's rate";
}

TEST(LapTiming, PacketsDroppedForABadChecksumAreLostSamplesToo) {
  FaultConfig faults;
  faults.corrupt_byte_rate = 0.0005;
  const VirtualRun run = scan_virtual_lidar(Model::TG30, 3.0, faults);
  ASSERT_GT(run.decoder.checksum_errors, 5u);
  const LapTimingStatistics t = timing_of(run.laps);
  // A broken zero packet merges two laps: that lap is an interruption, estimated, not exact.
  if (t.interruptions == 0) {
    EXPECT_EQ(t.lost_samples, truly_missing(run));
  } else {
    EXPECT_NEAR(static_cast<double>(t.lost_samples), static_cast<double>(truly_missing(run)),
                2.0 * static_cast<double>(t.interruptions));
  }
}

TEST(LapTiming, AStallIsAnInterruptionNotJitter) {
  FaultConfig faults;
  faults.stall_ms = 400;
  faults.stall_every_ms = 1500;
  const VirtualRun run = scan_virtual_lidar(Model::G6, 4.0, faults);
  ASSERT_GE(run.faults.stalls, 2u);
  const LapTimingStatistics t = timing_of(run.laps);
  EXPECT_GE(t.interruptions, 2u);
  EXPECT_LT(t.jitter_pct, 0.1);
  EXPECT_NEAR(t.mean_hz, 8.0, 0.01);
  // Issue 26: each stall is named once, where and how long, for the report and its plot.
  ASSERT_EQ(t.gaps.size(), run.faults.stalls);
  for (const TimingGap& gap : t.gaps) {
    EXPECT_EQ(gap.cause, TimingGap::Cause::Stall);
    EXPECT_NEAR(gap.to_s - gap.from_s, 0.4, 0.125 + 0.01) << "a 400 ms stall, give or take a lap at 8 Hz";
    EXPECT_NEAR(gap.turns_lost, 0.4 * 8.0, 1.5);
  }
  // Each 400 ms stall loses about 3.2 laps of 1125 samples; the estimate works in whole periods.
  const double missing = static_cast<double>(truly_missing(run));
  EXPECT_NEAR(static_cast<double>(t.lost_samples), missing, 0.15 * missing);
}

TEST(LapTiming, AMotorOffItsSetRateShowsInTheMeanNotInTheJitter) {
  FaultConfig faults;
  faults.scan_hz_offset = 0.5;
  const LapTimingStatistics t = timing_of(scan_virtual_lidar(Model::G6, 3.0, faults).laps);
  EXPECT_NEAR(t.mean_hz, 8.5, 0.01);
  EXPECT_LT(t.jitter_pct, 0.1);
  const double g6_rate = field_samples_per_s(Model::G6);
  EXPECT_NEAR(t.sample_rate_hz, g6_rate, 0.005 * g6_rate) << "the ranging clock does not care about the motor";
  EXPECT_EQ(t.lost_samples, 0u);
}

TEST(LapTiming, AWanderingMotorShowsInTheJitterNotInTheMean) {
  FaultConfig faults;
  faults.scan_hz_wobble = 0.3;  // +-3.75 % of 8 Hz, a sine of 2 s
  const LapTimingStatistics t = timing_of(scan_virtual_lidar(Model::G6, 4.0, faults).laps);
  // Robust std-dev of a sine of amplitude a is 1.4826 * a * sin(45 deg) = 1.05 a, here 3.9 %
  // (the samples per lap follow 1 / rate, so nearly the same share).
  EXPECT_NEAR(t.jitter_pct, 1.05 * 3.75, 0.5);
  EXPECT_NEAR(t.mean_hz, 8.0, 0.05);
  EXPECT_NEAR(t.min_hz, 7.7, 0.05);
  EXPECT_NEAR(t.max_hz, 8.3, 0.05);
  EXPECT_EQ(t.lost_samples, 0u);
}

TEST(LapTiming, AReadThatWokeLateIsNotAnInterruption) {
  // A busy host reads one lap's close 70 ms late (0.56 of a period): that period looks 1.56 long
  // and the next 0.44; nothing was lost and the rate did not change.
  std::vector<Lap> laps = scan_virtual_lidar(Model::G6, 3.0).laps;
  ASSERT_GT(laps.size(), 12u);
  laps[10].last_rx_ns += 70 * kMs;
  const LapTimingStatistics t = timing_of(laps);
  EXPECT_EQ(t.interruptions, 0u);
  EXPECT_EQ(t.lost_samples, 0u);
  EXPECT_NEAR(t.mean_hz, 8.0, 0.01);
  EXPECT_EQ(t.jitter_pct, 0.0);
}

TEST(LapTiming, AHostThatSleptAndCaughtUpInABurstIsNotAnInterruption) {
  // The reader sleeps 400 ms: four laps wait in the port's buffer and close together on waking.
  std::vector<Lap> laps = scan_virtual_lidar(Model::G6, 3.0).laps;
  ASSERT_GT(laps.size(), 16u);
  const std::int64_t woke = laps[13].last_rx_ns + 2 * kMs;
  for (std::size_t i = 10; i <= 13; ++i) laps[i].last_rx_ns = woke - static_cast<std::int64_t>(13 - i) * 100'000;
  const LapTimingStatistics t = timing_of(laps);
  EXPECT_EQ(t.interruptions, 0u);
  EXPECT_EQ(t.lost_samples, 0u);
  EXPECT_NEAR(t.mean_hz, 8.0, 0.05);
}

TEST(LapTiming, NoLapsGiveZeros) {
  const LapTimingStatistics t = LapTimingAccumulator{}.statistics();
  EXPECT_EQ(t.laps, 0u);
  EXPECT_EQ(t.mean_hz, 0.0);
}

}  // namespace
}  // namespace ydscope
