// The manuals' worked examples through the decoder, and how packets become laps.
#include <gtest/gtest.h>

#include "core/protocol/angle_correction.h"
#include "core/protocol/lap_assembler.h"
#include "core/protocol/reply.h"
#include "protocol_test_support.h"

namespace ydscope {
namespace {

using test::append;
using test::Bytes;
using test::decode;
using test::packet;

// One lap made of a zero packet, the given packet, and the closing zero packet.
Lap single_lap(const ModelProfile& profile, const Bytes& middle, std::optional<double> scale = std::nullopt) {
  Bytes stream = packet(kCtLapStart, 0.0, 0.0, {0});
  append(stream, middle);
  append(stream, packet(kCtLapStart, 0.0, 0.0, {0}));
  auto decoded = decode(profile, stream, {}, scale);
  EXPECT_EQ(decoded.laps.size(), 1u);
  return decoded.laps.empty() ? Lap{} : decoded.laps[0];
}

Bytes raw_packet(std::uint16_t fsa, std::uint16_t lsa, std::vector<std::uint16_t> samples) {
  Bytes out;
  append_scan_packet({0x00, fsa, lsa, samples}, out);
  return out;
}

TEST(ManualExamples, Distances) {
  // G1: sample E4 6F -> 7161 mm, flag 0.
  const Lap g1 = single_lap(profile_for(Model::G1), raw_packet(0x0001, 0x0001, {0x6FE4, 0x6FE6}));
  ASSERT_EQ(g1.points.size(), 3u);
  EXPECT_EQ(g1.points[1].range_mm, 7161.0f);
  EXPECT_EQ(g1.points[1].flag, PointFlag::None);
  EXPECT_EQ(g1.points[2].flag, PointFlag::Specular);
  // G6: sample E5 6F -> 7161.25 mm.
  const Lap g6 = single_lap(profile_for(Model::G6), raw_packet(0x0001, 0x0001, {0x6FE5}));
  EXPECT_EQ(g6.points[1].range_mm, 7161.25f);
  EXPECT_EQ(g6.points[1].flag, PointFlag::None);
  // TG: the same sample -> 14322.5 mm.
  for (Model tg : {Model::TG15, Model::TG30, Model::TG50}) {
    const Lap lap = single_lap(profile_for(tg), raw_packet(0x0001, 0x0001, {0x6FE5}));
    EXPECT_EQ(lap.points[1].range_mm, 14322.5f);
  }
  // The scale is overridable (vendor-SDK TG firmware above 1.2 uses S mm).
  const Lap tg_raw = single_lap(profile_for(Model::TG15), raw_packet(0x0001, 0x0001, {0x6FE5}), 1.0);
  EXPECT_EQ(tg_raw.points[1].range_mm, 28645.0f);
}

TEST(ManualExamples, AngleCorrection) {
  EXPECT_NEAR(angle_correction_deg(1000), -6.7622, 5e-5);
  EXPECT_NEAR(angle_correction_deg(8000), -7.8374, 5e-5);
  EXPECT_EQ(angle_correction_deg(0), 0.0);
  EXPECT_NEAR(angle_correction_deg(155.3), 0.0, 1e-12);  // at the baseline distance
}

TEST(ManualExamples, FirstAndSecondLevelAngles) {
  // LSN = 40, FSA = 0x6FE5, LSA = 0x79BD, Distance_1 = 1000, Distance_LSN = 8000 (G1 units: <<2).
  std::vector<std::uint16_t> samples(40, 0);
  samples.front() = 1000 << 2;
  samples.back() = 8000 << 2;
  const Lap lap = single_lap(profile_for(Model::G1), raw_packet(0x6FE5, 0x79BD, samples));
  ASSERT_EQ(lap.points.size(), 41u);
  const auto& first = lap.points[1];
  const auto& last = lap.points[40];
  // The manual rounds the first-level angles to 223.78/243.47 before correcting, giving 217.0178 and
  // 235.6326; unrounded (223.78125, 243.46875) the results differ by ~0.0013 degrees.
  EXPECT_NEAR(first.angle_deg, 217.0178, 0.002);
  EXPECT_NEAR(last.angle_deg, 235.6326, 0.002);
  EXPECT_NEAR(first.angle_deg, 223.78125 - 6.76220, 1e-4);
  EXPECT_NEAR(last.angle_deg, 243.46875 - 7.83739, 1e-4);
  // Intermediate angles: diff(19.6875) / 39 per step, no correction for distance 0.
  const double step = (243.46875 - 223.78125) / 39;
  EXPECT_NEAR(lap.points[2].angle_deg, 223.78125 + step, 1e-4);
  EXPECT_NEAR(lap.points[20].angle_deg, 223.78125 + 19 * step, 1e-4);
}

TEST(Angles, PacketCrossing360InterpolatesClockwise) {
  // 350 -> 10 degrees over 5 samples: 5 degree steps through 0.
  const Lap lap = single_lap(profile_for(Model::G6), packet(0, 350.0, 10.0, {0, 0, 0, 0, 0}));
  ASSERT_EQ(lap.points.size(), 6u);
  EXPECT_NEAR(lap.points[1].angle_deg, 350.0, 1e-4);
  EXPECT_NEAR(lap.points[2].angle_deg, 355.0, 1e-4);
  EXPECT_NEAR(lap.points[3].angle_deg, 0.0, 1e-4);
  EXPECT_NEAR(lap.points[4].angle_deg, 5.0, 1e-4);
  EXPECT_NEAR(lap.points[5].angle_deg, 10.0, 1e-4);
}

TEST(Angles, CorrectionBelowZeroIsNormalised) {
  // At 1 degree with 1000 mm the correction (-6.76) goes below 0: expect 354.24.
  const Lap lap = single_lap(profile_for(Model::G6), packet(0, 1.0, 1.0, {4000}));
  EXPECT_NEAR(lap.points[1].angle_deg, 1.0 - 6.76220 + 360.0, 1e-3);
  for (const auto& p : lap.points) {
    EXPECT_GE(p.angle_deg, 0.0f);
    EXPECT_LT(p.angle_deg, 360.0f);
  }
}

TEST(Angles, SingleSamplePacketHasNoDivision) {
  const Lap lap = single_lap(profile_for(Model::G6), packet(0, 123.0, 200.0, {0}));
  ASSERT_EQ(lap.points.size(), 2u);
  EXPECT_NEAR(lap.points[1].angle_deg, 123.0, 1e-4);
}

TEST(Angles, LsaBelowFsaWithoutRealWrapStillFollowsTheFormula) {
  // The X4 start-up packet: LSA < FSA means "crosses 360" by the formula: diff = 360 - 20 = 340.
  const Lap lap = single_lap(profile_for(Model::G6), packet(0, 100.0, 80.0, {0, 0, 0}));
  ASSERT_EQ(lap.points.size(), 4u);
  EXPECT_NEAR(lap.points[2].angle_deg, 100.0 + 170.0, 1e-4);
  EXPECT_NEAR(lap.points[3].angle_deg, 80.0, 1e-4);
}

TEST(Laps, OnlyCompleteLapsFromZeroPacketToZeroPacket) {
  Bytes stream = packet(0, 10.0, 20.0, {100, 100});  // before the first zero packet: discarded
  append(stream, packet(kCtLapStart, 0.0, 0.0, {40}));
  append(stream, packet(0, 10.0, 20.0, {100, 100, 100}));
  append(stream, packet(kCtLapStart, 0.0, 0.0, {40}));
  append(stream, packet(0, 10.0, 20.0, {100}));
  append(stream, packet(kCtLapStart, 0.0, 0.0, {40}));
  append(stream, packet(0, 10.0, 20.0, {100}));  // lap never closed
  const auto decoded = decode(profile_for(Model::G6), stream);
  ASSERT_EQ(decoded.laps.size(), 2u);
  EXPECT_EQ(decoded.laps[0].index, 0u);
  EXPECT_EQ(decoded.laps[0].points.size(), 4u);
  EXPECT_EQ(decoded.laps[0].packets, 2u);
  EXPECT_EQ(decoded.laps[1].index, 1u);
  EXPECT_EQ(decoded.laps[1].points.size(), 2u);
  EXPECT_FALSE(decoded.laps[0].scan_hz);  // no CT information outside G1
  EXPECT_EQ(decoded.laps[0].crc, CrcVerdict::NotApplicable);
  EXPECT_EQ(decoded.counters.laps, 2u);
  EXPECT_EQ(decoded.counters.discarded_packets, 1u);
  EXPECT_EQ(decoded.counters.zero_packets, 3u);
  EXPECT_EQ(decoded.counters.packets, 7u);
}

TEST(Laps, LapStartIsCtBitZeroOnly) {
  // Real devices set upper CT bits in normal packets (X2: CT 0x86); only bit 0 starts a lap.
  Bytes stream = packet(kCtLapStart | 0x40, 0.0, 0.0, {40});
  append(stream, packet(0x86, 10.0, 20.0, {100}));
  append(stream, packet(0xFE, 30.0, 40.0, {100}));
  append(stream, packet(0x03, 0.0, 0.0, {40}));
  const auto decoded = decode(profile_for(Model::G6), stream);
  ASSERT_EQ(decoded.laps.size(), 1u);
  EXPECT_EQ(decoded.laps[0].packets, 3u);
}

TEST(Laps, ChecksumErrorsAreCountedInTheirLap) {
  Bytes stream = packet(kCtLapStart, 0.0, 0.0, {40});
  Bytes bad = packet(0, 10.0, 20.0, {100, 200});
  bad[10] ^= 0x01;  // a sample bit flipped in transit
  append(stream, bad);
  append(stream, packet(0, 30.0, 40.0, {100}));
  append(stream, packet(kCtLapStart, 0.0, 0.0, {40}));
  const auto decoded = decode(profile_for(Model::G6), stream);
  ASSERT_EQ(decoded.laps.size(), 1u);
  EXPECT_EQ(decoded.laps[0].checksum_errors, 1u);
  EXPECT_EQ(decoded.laps[0].packets, 2u);
  EXPECT_EQ(decoded.counters.checksum_errors, 1u);
}

TEST(Laps, ReceiveTimestampsSpanTheLap) {
  Bytes stream = packet(kCtLapStart, 0.0, 0.0, {40});
  const std::size_t zero_size = stream.size();
  append(stream, packet(0, 10.0, 20.0, {100}));
  append(stream, packet(kCtLapStart, 0.0, 0.0, {40}));
  // decode() passes each chunk's offset as rx_ns; one chunk per packet-ish piece.
  const auto decoded = decode(profile_for(Model::G6), stream, {zero_size, 12, 12});
  ASSERT_EQ(decoded.laps.size(), 1u);
  EXPECT_EQ(decoded.laps[0].first_rx_ns, 0);
  EXPECT_EQ(decoded.laps[0].last_rx_ns, static_cast<std::int64_t>(zero_size + 12));
}

TEST(G1, CtInformationAndCrcVerdict) {
  test::G1LapSpec spec;
  spec.scan_hz = 9.6;
  spec.major = 2;
  spec.minor = 17;
  spec.health = kG1HealthSensor | kG1HealthData;
  Bytes stream;
  const std::uint8_t crc1 = test::append_g1_lap(stream, spec, 0x00);  // LastCRC of an unseen lap
  const std::uint8_t crc2 = test::append_g1_lap(stream, spec, crc1);
  const std::uint8_t crc3 = test::append_g1_lap(stream, spec, static_cast<std::uint8_t>(crc2 ^ 0xFF));
  test::append_g1_lap(stream, spec, crc3);
  const auto decoded = decode(profile_for(Model::G1), stream);
  ASSERT_EQ(decoded.laps.size(), 3u);
  const Lap& lap = decoded.laps[0];
  EXPECT_EQ(lap.crc, CrcVerdict::Ok);
  EXPECT_TRUE(lap.ct_info_trusted());
  ASSERT_TRUE(lap.scan_hz);
  EXPECT_DOUBLE_EQ(*lap.scan_hz, 9.6);
  ASSERT_TRUE(lap.version);
  EXPECT_EQ(lap.version->major, 2);
  EXPECT_EQ(lap.version->minor, 17);
  ASSERT_TRUE(lap.health_bits);
  EXPECT_EQ(*lap.health_bits, kG1HealthSensor | kG1HealthData);
  EXPECT_EQ(lap.packets, 7u);
  EXPECT_EQ(lap.points.size(), 1u + 6u * 10u);
  EXPECT_EQ(decoded.laps[1].crc, CrcVerdict::Mismatch);
  EXPECT_FALSE(decoded.laps[1].ct_info_trusted());
  EXPECT_EQ(decoded.counters.crc_ok, 2u);
  EXPECT_EQ(decoded.counters.crc_mismatches, 1u);
  EXPECT_EQ(decoded.laps[2].crc, CrcVerdict::Ok);
  // LastCRC bytes are not resync noise.
  EXPECT_EQ(decoded.counters.resync_bytes, 0u);
}

TEST(G1, LostPacketMakesTheCrcFail) {
  test::G1LapSpec spec;
  Bytes first;
  const std::uint8_t crc = test::append_g1_lap(first, spec, 0x00);
  Bytes lap2;
  const std::uint8_t crc2 = test::append_g1_lap(lap2, spec, crc);
  // Drop the lap's second packet (the version packet) from the stream, as a lossy link would.
  const std::size_t zero_end = 1 + packet_size(1);
  const std::size_t second_end = zero_end + packet_size(static_cast<std::uint8_t>(spec.lsn));
  Bytes stream = first;
  append(stream, Bytes(lap2.begin(), lap2.begin() + static_cast<std::ptrdiff_t>(zero_end)));
  append(stream, Bytes(lap2.begin() + static_cast<std::ptrdiff_t>(second_end), lap2.end()));
  test::append_g1_lap(stream, spec, crc2);
  const auto decoded = decode(profile_for(Model::G1), stream);
  ASSERT_EQ(decoded.laps.size(), 2u);
  EXPECT_EQ(decoded.laps[0].crc, CrcVerdict::Ok);
  EXPECT_EQ(decoded.laps[1].crc, CrcVerdict::Mismatch);
  // Index 3 is now a production packet: the "health" read from it is not to be trusted.
  EXPECT_FALSE(decoded.laps[1].ct_info_trusted());
}

// Issue 17: this was a Mismatch (crc_ok false), but with no byte there is nothing to compare.
TEST(G1, MissingLastCrcByteIsAnUnknownVerdict) {
  test::G1LapSpec spec;
  Bytes stream;
  test::append_g1_lap(stream, spec, 0x00);
  Bytes next;
  test::append_g1_lap(next, spec, 0x00);
  append(stream, Bytes(next.begin() + 1, next.end()));  // zero packet right after the last packet
  test::append_g1_lap(stream, spec, 0x00);
  const auto decoded = decode(profile_for(Model::G1), stream);
  ASSERT_EQ(decoded.laps.size(), 2u);
  EXPECT_EQ(decoded.laps[0].crc, CrcVerdict::Unknown);
  EXPECT_TRUE(decoded.laps[0].ct_info_trusted());
  EXPECT_EQ(decoded.laps[1].crc, CrcVerdict::Ok);
  EXPECT_EQ(decoded.counters.crc_unknown, 1u);
  EXPECT_EQ(decoded.counters.crc_mismatches, 0u);
}

// Issue 17 asked which byte counts when several lie between a lap's last packet and its closing
// zero packet: the one right before the zero packet (docs/cli.md, decode's output). Junk before the
// true LastCRC leaves the verdict Ok; junk after it (so it is no longer right before) is a Mismatch.
TEST(G1, WithSeveralBytesBeforeAZeroPacketTheLastOneIsTheLastCrc) {
  test::G1LapSpec spec;
  Bytes first;
  const std::uint8_t crc = test::append_g1_lap(first, spec, 0x00);
  const auto with_gap = [&](const Bytes& gap) {
    Bytes stream = first;
    Bytes next;
    test::append_g1_lap(next, spec, 0x00);
    append(stream, gap);
    append(stream, Bytes(next.begin() + 1, next.end()));  // the zero packet right after the gap
    test::append_g1_lap(stream, spec, 0x00);
    return decode(profile_for(Model::G1), stream);
  };
  const auto junk_first = with_gap({0x13, 0x37, crc});
  ASSERT_EQ(junk_first.laps.size(), 2u);
  EXPECT_EQ(junk_first.laps[0].crc, CrcVerdict::Ok);
  const auto junk_last = with_gap({crc, 0x13});
  ASSERT_EQ(junk_last.laps.size(), 2u);
  EXPECT_EQ(junk_last.laps[0].crc, crc == 0x13 ? CrcVerdict::Ok : CrcVerdict::Mismatch);
  EXPECT_FALSE(junk_last.laps[0].ct_info_trusted());
}

// A stream fed packet by packet, each with its own receive time (ns).
std::vector<Lap> decode_timed(const std::vector<std::pair<Bytes, std::int64_t>>& packets,
                              DecoderCounters* counters = nullptr) {
  ScanDecoder decoder(profile_for(Model::G6));
  std::vector<Lap> laps;
  for (const auto& [bytes, rx_ns] : packets) decoder.feed(bytes, rx_ns, [&](const Lap& lap) { laps.push_back(lap); });
  if (counters) *counters = decoder.counters();
  return laps;
}

TEST(Laps, ALostZeroPacketCutsTheLapWhereItComesRound) {
  Bytes stream = packet(kCtLapStart, 0.0, 0.0, {40});
  for (double a = 10.0; a < 350.0; a += 40.0) append(stream, packet(0, a, a + 30.0, {100, 100}));
  // The next zero packet was lost: the angle passes 0 again, then the lap after it closes.
  append(stream, packet(0, 2.0, 30.0, {100, 100}));
  append(stream, packet(0, 40.0, 70.0, {100, 100}));
  append(stream, packet(kCtLapStart, 0.0, 0.0, {40}));
  append(stream, packet(0, 10.0, 40.0, {100, 100}));
  append(stream, packet(kCtLapStart, 0.0, 0.0, {40}));
  const auto decoded = decode(profile_for(Model::G6), stream);
  ASSERT_EQ(decoded.laps.size(), 2u);
  EXPECT_EQ(decoded.laps[0].end, LapEnd::MissedZeroPacket);
  EXPECT_EQ(decoded.laps[0].packets, 10u);  // the zero packet and the nine up to 330 degrees
  EXPECT_FALSE(decoded.laps[0].whole());
  EXPECT_EQ(decoded.laps[1].end, LapEnd::ZeroPacket);
  EXPECT_TRUE(decoded.laps[1].whole());
  EXPECT_EQ(decoded.counters.cut_laps, 1u);
  EXPECT_EQ(decoded.counters.discarded_packets, 2u);  // the turn after the cut, up to the zero packet
}

TEST(Laps, APacketStartingAHairBehindTheLastIsNoNewTurn) {
  // The X4's start-up lap: 223.34 then 222.64 degrees. Read as 359.3 degrees on, it would cut a
  // whole lap short.
  Bytes stream = packet(kCtLapStart, 0.0, 0.0, {40});
  append(stream, packet(0, 100.0, 223.34, {100, 100}));
  append(stream, packet(0, 222.64, 300.0, {100, 100}));
  append(stream, packet(0, 300.0, 359.0, {100, 100}));
  append(stream, packet(kCtLapStart, 0.0, 0.0, {40}));
  const auto decoded = decode(profile_for(Model::G6), stream);
  ASSERT_EQ(decoded.laps.size(), 1u);
  EXPECT_EQ(decoded.laps[0].end, LapEnd::ZeroPacket);
  EXPECT_EQ(decoded.laps[0].packets, 4u);
}

TEST(Laps, AStallThatResumesElsewhereCutsTheLap) {
  constexpr std::int64_t ms = 1'000'000;
  DecoderCounters counters;
  const auto laps = decode_timed({{packet(kCtLapStart, 0.0, 0.0, {40}), 0},
                                  {packet(0, 10.0, 40.0, {100, 100}), 5 * ms},
                                  {packet(0, 40.5, 70.0, {100, 100}), 10 * ms},
                                  // 3 s of nothing; the lidar turned on meanwhile
                                  {packet(0, 200.0, 230.0, {100, 100}), 3010 * ms},
                                  {packet(0, 230.5, 260.0, {100, 100}), 3015 * ms},
                                  {packet(kCtLapStart, 0.0, 0.0, {40}), 3100 * ms},
                                  {packet(0, 10.0, 40.0, {100, 100}), 3105 * ms},
                                  {packet(kCtLapStart, 0.0, 0.0, {40}), 3200 * ms}},
                                 &counters);
  ASSERT_EQ(laps.size(), 2u);
  EXPECT_EQ(laps[0].end, LapEnd::Stall);
  EXPECT_EQ(laps[0].packets, 3u);
  EXPECT_EQ(laps[0].last_rx_ns, 10 * ms);  // the lap ends where the stream went quiet
  EXPECT_FALSE(laps[0].whole());
  EXPECT_EQ(laps[1].end, LapEnd::ZeroPacket);
  EXPECT_TRUE(laps[1].whole());
  EXPECT_EQ(counters.cut_laps, 1u);
}

TEST(Laps, ALateReadThatLostNothingKeepsTheLapButItTimesNothing) {
  // The host read 400 ms late and every byte was still there: the packet follows on from the
  // last, so the lap is whole in angle, but its duration is the host's, not the motor's.
  constexpr std::int64_t ms = 1'000'000;
  const auto laps = decode_timed({{packet(kCtLapStart, 0.0, 0.0, {40}), 0},
                                  {packet(0, 10.0, 40.0, {100, 100}), 5 * ms},
                                  {packet(0, 40.5, 70.0, {100, 100}), 405 * ms},
                                  {packet(kCtLapStart, 0.0, 0.0, {40}), 410 * ms}});
  ASSERT_EQ(laps.size(), 1u);
  EXPECT_EQ(laps[0].end, LapEnd::ZeroPacket);
  EXPECT_EQ(laps[0].packets, 3u);
  EXPECT_EQ(laps[0].longest_wait_ns, 400 * ms);
  EXPECT_FALSE(laps[0].whole());
}

TEST(Laps, PointStorageIsBounded) {
  // A stream that never sends the next zero packet cannot grow a lap past Lap::kMaxPoints.
  Bytes stream = packet(kCtLapStart, 0.0, 0.0, {40});
  const std::size_t packets = Lap::kMaxPoints / 255 + 2;
  for (std::size_t i = 0; i < packets; ++i) append(stream, packet(0, 10.0, 20.0, std::vector<std::uint16_t>(255, 100)));
  append(stream, packet(kCtLapStart, 0.0, 0.0, {40}));
  const auto decoded = decode(profile_for(Model::G6), stream);
  ASSERT_EQ(decoded.laps.size(), 1u);
  EXPECT_EQ(decoded.laps[0].points.size(), Lap::kMaxPoints);
  EXPECT_EQ(decoded.counters.overflow_points, 1 + packets * 255 - Lap::kMaxPoints);
  // Issue 17: the cut was silent; the lap itself now says how many points it lost.
  EXPECT_EQ(decoded.laps[0].cut_points, 1 + packets * 255 - Lap::kMaxPoints);
}

}  // namespace
}  // namespace ydscope
