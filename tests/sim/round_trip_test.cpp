// The virtual lidar's stream decoded by the real ScanDecoder gives back exactly the scene's points,
// and with faults on, exactly the injected losses. Time is injected: no sleeping.
#include <gtest/gtest.h>

#include <cmath>
#include <map>

#include "core/protocol/scan_decoder.h"
#include "core/sim/virtual_lidar.h"
#include "sim/sim_test_support.h"
#include "support/field_decoder.h"

namespace ydscope {
namespace {

using test::kMs;

struct ScanRun {
  std::vector<TruthPacket> packets;  // every packet generated, in order
  std::vector<Lap> laps;             // what the decoder published
  DecoderCounters decoder;
  DeviceCounters device;
  FaultCounters faults;
  std::uint64_t bytes = 0;
};

// Scans for `duration` with the decoder fed every 5 ms, as a host reading a port would be.
ScanRun scan(const VirtualLidarConfig& config, std::int64_t duration) {
  ScanRun run;
  VirtualLidar lidar(config);
  lidar.set_truth([&](const TruthPacket& packet) { run.packets.push_back(packet); });
  ScanDecoder decoder(lidar.profile(), lidar.conventions(), lidar.distance_scale());
  std::int64_t now = 0;
  lidar.receive(test::bytes({0xA5, 0x60}), now);
  std::vector<std::uint8_t> out;
  while (now < duration) {
    now += 5 * kMs;
    out.clear();
    lidar.produce(now, out);
    run.bytes += out.size();
    decoder.feed(out, now, [&](const Lap& lap) { run.laps.push_back(lap); });
  }
  run.decoder = decoder.counters();
  run.device = lidar.counters();
  run.faults = lidar.fault_counters();
  return run;
}

// The points a correct host decodes for lap k: those of its packets that reached it intact.
std::map<std::uint64_t, std::vector<LapPoint>> truth_laps(const ScanRun& run) {
  std::map<std::uint64_t, std::vector<LapPoint>> laps;
  for (const auto& packet : run.packets) {
    if (packet.lost || packet.corrupted) continue;
    auto& points = laps[packet.lap];
    points.insert(points.end(), packet.points.begin(), packet.points.end());
  }
  return laps;
}

double angle_gap(double a, double b) {
  const double d = std::fabs(a - b);
  return std::min(d, 360.0 - d);
}

void expect_laps_match_truth(const ScanRun& run) {
  const auto truth = truth_laps(run);
  ASSERT_FALSE(run.laps.empty());
  for (const Lap& lap : run.laps) {
    ASSERT_TRUE(truth.count(lap.index)) << "lap " << lap.index;
    const auto& expected = truth.at(lap.index);
    ASSERT_EQ(lap.points.size(), expected.size()) << "lap " << lap.index;
    for (std::size_t i = 0; i < expected.size(); ++i) {
      // Angles: both sides interpolate the same 1/64-degree FSA/LSA; only the correction's
      // float rounding differs. Ranges: the same raw value times the same scale.
      ASSERT_LE(angle_gap(lap.points[i].angle_deg, expected[i].angle_deg), 0.5 / 64)
          << "lap " << lap.index << " point " << i;
      ASSERT_NEAR(lap.points[i].range_mm, expected[i].range_mm, 1e-3) << "lap " << lap.index << " point " << i;
      ASSERT_EQ(lap.points[i].flag, expected[i].flag) << "lap " << lap.index << " point " << i;
    }
  }
}

class RoundTrip : public ::testing::TestWithParam<std::tuple<Model, const char*>> {
 protected:
  VirtualLidarConfig config() const {
    VirtualLidarConfig c;
    c.model = std::get<0>(GetParam());
    c.scene = std::get<1>(GetParam());
    c.seed = 11;
    return c;
  }
};

TEST_P(RoundTrip, DecoderGivesBackTheScenesPointsWithNoErrors) {
  const ScanRun run = scan(config(), 2'000 * kMs);
  expect_laps_match_truth(run);
  EXPECT_EQ(run.decoder.checksum_errors, 0u);
  EXPECT_EQ(run.decoder.packets, run.device.packets_sent);
  EXPECT_GE(run.device.packets, run.device.packets_sent);  // the rest are still queued for the line
  EXPECT_LE(run.device.packets, run.device.packets_sent + 3);
  EXPECT_EQ(run.laps.size() + 1, run.decoder.zero_packets);  // the last lap is still open
  const bool g1 = std::get<0>(GetParam()) == Model::G1;
  for (const Lap& lap : run.laps) {
    EXPECT_EQ(lap.crc, g1 ? CrcVerdict::Ok : CrcVerdict::NotApplicable);
    if (g1) {
      ASSERT_TRUE(lap.scan_hz.has_value());
      EXPECT_DOUBLE_EQ(*lap.scan_hz, 9.0);
      EXPECT_EQ(lap.health_bits, std::optional<std::uint8_t>(0));
      ASSERT_TRUE(lap.version.has_value());
      EXPECT_EQ(lap.version->major, 1);
      EXPECT_EQ(lap.version->minor, 2);
    }
  }
  EXPECT_EQ(run.decoder.crc_ok, g1 ? run.laps.size() : 0u);
}

TEST_P(RoundTrip, PointsLieOnTheSceneAfterTheHostsAngleCorrection) {
  const ScanRun run = scan(config(), 1'000 * kMs);
  std::size_t points = 0;
  std::size_t no_return = 0;
  for (const auto& packet : run.packets) {
    for (std::size_t i = 0; i < packet.points.size(); ++i) {
      ++points;
      if (packet.points[i].range_mm == 0.0f) {
        ++no_return;  // no direction to check: open window, or a dropped pixel at an edge
        continue;
      }
      ASSERT_LT(angle_gap(packet.points[i].angle_deg, packet.scene_angle_deg[i]), 0.011)
          << "lap " << packet.lap << " packet " << packet.index << " point " << i;
    }
  }
  // Edges where no direction is consistent (the parallax shadow) and the room's window are few.
  EXPECT_LT(static_cast<double>(no_return), 0.15 * static_cast<double>(points));
}

// The virtual lidar imitates real units by default (G6 S/2 mm at 18 k samples/s, TG S mm with no
// correction, TG's byte before the zero packet); the manual's literal reading stays a mode, and
// the decoder reading it the manual's way gives back the same points as before.
TEST_P(RoundTrip, TheManualsReadingStillGivesBackTheScenesPoints) {
  VirtualLidarConfig c = config();
  c.reading = Reading::Manual;
  const ScanRun run = scan(c, 1'000 * kMs);
  expect_laps_match_truth(run);
  EXPECT_EQ(run.decoder.checksum_errors, 0u);
  EXPECT_EQ(run.decoder.resync_bytes, 7u) << "only the scan reply header";
}

TEST_P(RoundTrip, TheFieldsReadingLosesNoByteToResync) {
  const ScanRun run = scan(config(), 1'000 * kMs);
  EXPECT_EQ(run.decoder.resync_bytes, 7u) << "TG's byte before the zero packet is understood, not noise";
}

// A TG on firmware the vendor SDK calls old (its major <= 1 and minor <= 2 in its byte order: the
// manual's "2.1") writes S/2 mm; the host picks that row from the same A5 90 bytes.
TEST(RoundTripFirmware, AnOldTgWritesHalfMillimetresAndIsReadSo) {
  VirtualLidarConfig c;
  c.model = Model::TG30;
  c.scene = "room";
  c.firmware_major = 2;  // the manual's order: byte 1
  c.firmware_minor = 1;
  const VirtualLidar probe(c);
  EXPECT_EQ(probe.conventions().id, "tg-field-fw1.2");
  EXPECT_EQ(probe.distance_scale(), 0.5);
  EXPECT_EQ(&probe.conventions(),
            &conventions_for(profile_for(Model::TG30), firmware_as_sdk_reads(2, 1), Reading::Field));
  const ScanRun run = scan(c, 1'000 * kMs);
  expect_laps_match_truth(run);
  EXPECT_EQ(run.decoder.checksum_errors, 0u);
}

TEST_P(RoundTrip, LapsComeAtTheSetScanFrequencyWithinTheLineRate) {
  const VirtualLidarConfig c = config();
  const ScanRun run = scan(c, 3'000 * kMs);
  const ModelProfile& profile = profile_for(c.model);
  ASSERT_GE(run.laps.size(), 10u);
  const double period_ns = static_cast<double>(run.laps.back().last_rx_ns - run.laps.front().last_rx_ns) /
                           static_cast<double>(run.laps.size() - 1);
  EXPECT_NEAR(1e9 / period_ns, profile.default_scan_hz, 0.1);
  EXPECT_LE(static_cast<double>(run.bytes), 3.0 * profile.default_baud / 10.0);
  const double per_lap = static_cast<double>(run.laps[3].points.size());
  // As a real unit: the conventions' samples per second at the default ranging code.
  EXPECT_NEAR(per_lap, test::field_samples_per_s(c.model) / profile.default_scan_hz, 1.0);
}

INSTANTIATE_TEST_SUITE_P(ModelsAndScenes, RoundTrip,
                         ::testing::Combine(::testing::Values(Model::G1, Model::G6, Model::TG15, Model::TG30,
                                                              Model::TG50),
                                            ::testing::Values("room", "demo", "booth")),
                         [](const auto& param) {
                           return std::string(profile_for(std::get<0>(param.param)).name) + "_" +
                                  std::get<1>(param.param);
                         });

VirtualLidarConfig faulty(Model model, const char* scene = "room") {
  VirtualLidarConfig c;
  c.model = model;
  c.scene = scene;
  c.seed = 5;
  return c;
}

// The corrupted packets that went out whole: the checksum errors a host must count. Faults are
// counted as a packet is made, so those still on their way when a run ends (on the line, or
// queued behind it) are left out; packets leave in the order they are made.
std::uint64_t corrupted_and_sent(const ScanRun& run) {
  const std::uint64_t unsent =
      run.device.packets - run.device.packets_sent - run.faults.lost_packets - run.faults.stalled_packets;
  std::uint64_t count = 0;
  for (std::size_t i = 0; i + unsent < run.packets.size(); ++i) count += run.packets[i].corrupted ? 1 : 0;
  return count;
}

TEST(RoundTripFaults, LostPacketsFailExactlyTheirLapsCrcOnG1) {
  VirtualLidarConfig c = faulty(Model::G1);
  c.faults.lost_packet_rate = 0.02;
  const ScanRun run = scan(c, 4'000 * kMs);
  ASSERT_GT(run.faults.lost_packets, 5u);
  expect_laps_match_truth(run);
  EXPECT_EQ(run.decoder.packets, run.device.packets_sent);  // lost packets never reach the line
  std::uint64_t truth_lost = 0;
  for (const auto& p : run.packets) truth_lost += p.lost;
  EXPECT_EQ(truth_lost, run.faults.lost_packets);
  std::map<std::uint64_t, bool> lap_lost;
  for (const auto& p : run.packets) lap_lost[p.lap] = lap_lost[p.lap] || p.lost;
  std::uint64_t expected_mismatches = 0;
  for (const Lap& lap : run.laps) {
    EXPECT_EQ(lap.crc, lap_lost[lap.index] ? CrcVerdict::Mismatch : CrcVerdict::Ok) << "lap " << lap.index;
    expected_mismatches += lap_lost[lap.index] ? 1 : 0;
  }
  EXPECT_GT(expected_mismatches, 0u);
  EXPECT_EQ(run.decoder.crc_mismatches, expected_mismatches);
  EXPECT_EQ(run.decoder.checksum_errors, 0u);
}

TEST(RoundTripFaults, CorruptedPacketsAreExactlyTheChecksumErrors) {
  VirtualLidarConfig c = faulty(Model::G6);
  c.faults.corrupt_byte_rate = 0.0005;
  const ScanRun run = scan(c, 4'000 * kMs);
  ASSERT_GT(run.faults.corrupted_packets, 5u);
  EXPECT_GE(run.faults.corrupted_bytes, run.faults.corrupted_packets);
  expect_laps_match_truth(run);
  EXPECT_EQ(run.decoder.packets + run.faults.corrupted_packets, run.device.packets_sent);
  EXPECT_EQ(run.decoder.checksum_errors, corrupted_and_sent(run));
}

// Two flips of the same bit in the same byte lane cancel in the XOR checksum: the host takes the
// packet as good. The truth marks it altered (not corrupted), so a test can tell the laps that
// carry other values than the device measured from the laps no fault touched.
TEST(RoundTripFaults, FlipsThatCancelInTheChecksumAreMarkedAlteredNotCorrupted) {
  VirtualLidarConfig c = faulty(Model::G6);
  c.faults.corrupt_byte_rate = 0.01;  // high, so that pairs that cancel happen in a short run
  const ScanRun run = scan(c, 3'000 * kMs);
  std::size_t altered = 0;
  for (const TruthPacket& packet : run.packets) {
    EXPECT_FALSE(packet.altered && packet.corrupted);
    altered += packet.altered ? 1 : 0;
  }
  ASSERT_GT(altered, 0u) << "no two flips cancelled; raise the rate";
  // The host cannot tell: the altered packets are not among its checksum errors.
  EXPECT_EQ(run.decoder.checksum_errors, corrupted_and_sent(run));
}

TEST(RoundTripFaults, DroppedBytesAreMissingFromWhatTheHostReads) {
  const ScanRun clean = scan(faulty(Model::TG30), 2'000 * kMs);
  VirtualLidarConfig c = faulty(Model::TG30);
  c.faults.drop_byte_rate = 0.001;
  const ScanRun run = scan(c, 2'000 * kMs);
  ASSERT_GT(run.faults.dropped_bytes, 10u);
  EXPECT_EQ(run.bytes + run.faults.dropped_bytes, clean.bytes);
  EXPECT_EQ(run.decoder.bytes, run.bytes);
  EXPECT_LT(run.decoder.packets, clean.decoder.packets);
  // A dropped byte spoils at most two packets (its own, and the next one when it ate the header).
  EXPECT_GE(run.decoder.packets + 2 * run.faults.dropped_bytes, clean.decoder.packets);
}

TEST(RoundTripFaults, HealthBitsRideInG1CtAndTheLapStillChecksOut) {
  VirtualLidarConfig c = faulty(Model::G1, "demo");
  c.faults.health_bits = 0x21;
  const ScanRun run = scan(c, 1'000 * kMs);
  ASSERT_FALSE(run.laps.empty());
  for (const Lap& lap : run.laps) {
    EXPECT_EQ(lap.health_bits, std::optional<std::uint8_t>(0x21));
    EXPECT_EQ(lap.crc, CrcVerdict::Ok);
  }
}

TEST(RoundTripFaults, InterferenceFlagsAppearOnlyOnG1) {
  for (const Model model : {Model::G1, Model::G6}) {
    const ScanRun run = scan(faulty(model, "room"), 2'000 * kMs);
    std::size_t specular = 0;
    std::size_t ambient = 0;
    for (const Lap& lap : run.laps)
      for (const LapPoint& p : lap.points) {
        specular += p.flag == PointFlag::Specular;
        ambient += p.flag == PointFlag::AmbientLight;
      }
    if (model == Model::G1) {
      EXPECT_GT(specular, 50u);  // the mirror
      EXPECT_GT(ambient, 20u);   // the sunlit window
    } else {
      EXPECT_EQ(specular + ambient, 0u);
    }
  }
}

TEST(RoundTripFaults, AStallSendsNothingForItsDurationAndLosesItsPackets) {
  VirtualLidarConfig c = faulty(Model::G6);
  VirtualLidar lidar(c);
  std::uint64_t truth_stalled = 0;
  lidar.set_truth([&](const TruthPacket& p) { truth_stalled += p.lost; });
  std::int64_t now = 0;
  lidar.receive(test::bytes({0xA5, 0x60}), now);
  test::run_for(lidar, now, 500 * kMs, kMs);
  lidar.stall(now, 300 * kMs);
  std::vector<std::uint8_t> out;
  std::size_t bytes_in_stall = 0;
  for (int ms = 1; ms <= 300; ++ms) {
    out.clear();
    lidar.produce(now + ms * kMs, out);
    if (ms > 2) bytes_in_stall += out.size();  // the packet in flight at the start may finish
  }
  now += 300 * kMs;
  EXPECT_EQ(bytes_in_stall, 0u);
  EXPECT_FALSE(test::run_for(lidar, now, 50 * kMs).empty());  // and then it sends again
  EXPECT_EQ(lidar.fault_counters().stalls, 1u);
  EXPECT_GT(lidar.fault_counters().stalled_packets, 50u);
  EXPECT_EQ(lidar.fault_counters().stalled_packets, truth_stalled);
}

// Every sample the blocked sector empties is counted, as every other injected fault is: exactly the
// empty samples whose direction lies in the sector, about its share of all samples.
TEST(RoundTripFaults, ABlockedSectorIsCountedSampleBySample) {
  VirtualLidarConfig config;
  config.model = Model::G6;
  config.scene = "room";
  config.faults.blocked_from_deg = 40.0;
  config.faults.blocked_width_deg = 35.0;
  const ScanRun run = scan(config, 2000 * kMs);
  std::uint64_t samples = 0, empty_in_sector = 0;
  for (const TruthPacket& packet : run.packets)
    for (const LapPoint& point : packet.points) {
      ++samples;
      empty_in_sector += point.range_mm == 0.0f && std::fmod(point.angle_deg - 40.0 + 360.0, 360.0) < 35.0;
    }
  EXPECT_EQ(run.faults.blocked_samples, empty_in_sector);
  EXPECT_NEAR(static_cast<double>(run.faults.blocked_samples) / static_cast<double>(samples), 35.0 / 360.0, 0.01);

  config.faults.blocked_width_deg = 0.0;
  EXPECT_EQ(scan(config, 500 * kMs).faults.blocked_samples, 0u);
}

TEST(RoundTripFaults, PeriodicStallsRecur) {
  VirtualLidarConfig c = faulty(Model::G6);
  c.faults.stall_ms = 100;
  c.faults.stall_every_ms = 1'000;
  VirtualLidar lidar(c);
  std::int64_t now = 0;
  lidar.receive(test::bytes({0xA5, 0x60}), now);
  test::run_for(lidar, now, 3'500 * kMs);
  EXPECT_EQ(lidar.fault_counters().stalls, 3u);
}

TEST(RoundTripFaults, JunkComesBeforeEveryReplyHeader) {
  VirtualLidarConfig c = faulty(Model::G6);
  c.faults.junk_before_reply = 9;
  VirtualLidar lidar(c);
  std::int64_t now = 0;
  const auto reply = test::exchange(lidar, {0xA5, 0x90}, now);
  ASSERT_EQ(reply.size(), 9u + 27u);
  for (std::size_t i = 0; i < 9; ++i) EXPECT_NE(reply[i], 0xA5);
  EXPECT_EQ(reply[9], 0xA5);
  EXPECT_EQ(reply[10], 0x5A);
  EXPECT_EQ(lidar.fault_counters().junk_bytes, 9u);
}

TEST(RoundTripFaults, TheSameSeedGivesTheSameBytes) {
  VirtualLidarConfig c = faulty(Model::G1);
  c.faults.lost_packet_rate = 0.01;
  c.faults.corrupt_byte_rate = 0.001;
  std::vector<std::uint8_t> first;
  std::vector<std::uint8_t> second;
  for (auto* out : {&first, &second}) {
    VirtualLidar lidar(c);
    std::int64_t now = 0;
    lidar.receive(test::bytes({0xA5, 0x60}), now);
    *out = test::run_for(lidar, now, 1'000 * kMs);
  }
  EXPECT_EQ(first, second);
  c.seed = 6;
  VirtualLidar other(c);
  std::int64_t now = 0;
  other.receive(test::bytes({0xA5, 0x60}), now);
  EXPECT_NE(test::run_for(other, now, 1'000 * kMs), first);
}

}  // namespace
}  // namespace ydscope
