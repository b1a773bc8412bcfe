// Real device bytes (tests/data/captures), decoded with the G6 formulas as their README says.
// Every count below was checked independently of this decoder by walking each file packet by
// packet from its known start (offset 7 after the A5 5A 05 00 00 40 81 reply header; offset 10 in
// the X4-class file) with a separate script: sizes 10 + 2*LSN chain exactly to the cut-off tail.
#include <gtest/gtest.h>

#include "protocol_test_support.h"

namespace ydscope {
namespace {

using test::Bytes;
using test::decode;

struct CaptureCounts {
  const char* file;
  std::uint64_t bytes, packets, zero_packets, laps, discarded, pending, cut_laps;
};

class X4Capture : public ::testing::TestWithParam<CaptureCounts> {};

TEST_P(X4Capture, DecodesWithExactCounts) {
  const CaptureCounts expected = GetParam();
  const Bytes bytes = test::read_file(test::capture(expected.file));
  ASSERT_EQ(bytes.size(), expected.bytes);
  const auto decoded = decode(profile_for(Model::G6), bytes);
  const auto& c = decoded.counters;
  EXPECT_EQ(c.packets, expected.packets);
  EXPECT_EQ(c.zero_packets, expected.zero_packets);
  EXPECT_EQ(c.checksum_errors, 0u);
  EXPECT_EQ(c.resync_bytes, 7u);                 // exactly the scan reply header
  EXPECT_EQ(c.pending_bytes, expected.pending);  // the cut-off packet at the end
  EXPECT_EQ(c.laps, expected.laps);
  EXPECT_EQ(c.discarded_packets, expected.discarded);
  EXPECT_EQ(c.cut_laps, expected.cut_laps);
  ASSERT_EQ(decoded.laps.size(), expected.laps);
  std::uint64_t packets_in_laps = 0;
  for (const Lap& lap : decoded.laps) {
    packets_in_laps += lap.packets;
    EXPECT_EQ(lap.checksum_errors, 0u);
    EXPECT_EQ(lap.crc, CrcVerdict::NotApplicable);
    EXPECT_FALSE(lap.scan_hz);
    for (const LapPoint& p : lap.points) {
      ASSERT_GE(p.angle_deg, 0.0f);
      ASSERT_LT(p.angle_deg, 360.0f);
      ASSERT_EQ(p.flag, PointFlag::None);
    }
  }
  // Every packet is in a lap except those before the first zero packet and in the unfinished last lap.
  EXPECT_LT(packets_in_laps, c.packets - c.discarded_packets);
  // Chunked arrival gives the same counts.
  const auto chunked = decode(profile_for(Model::G6), bytes, {1, 3, 64, 517, 4096});
  EXPECT_EQ(chunked.counters.packets, c.packets);
  EXPECT_EQ(chunked.counters.laps, c.laps);
  EXPECT_EQ(chunked.counters.resync_bytes, c.resync_bytes);
}

// packets/zero packets/tail from the independent walk; laps = zero packets - 1 (the last lap is
// cut off); discarded = packets before the first zero packet (scan1: 7, scan2/3 start with one)
// and, in scan2, the 29 packets of the start-up lap's second turn (see X4Scan2StartUpLap).
INSTANTIATE_TEST_SUITE_P(Captures, X4Capture,
                         ::testing::Values(CaptureCounts{"x4-scan1.bin", 38074, 455, 28, 27, 7, 75, 0},
                                           CaptureCounts{"x4-scan2.bin", 98769, 1243, 71, 70, 29, 74, 1},
                                           CaptureCounts{"x4-scan3.bin", 156209, 1949, 114, 113, 0, 74, 0}),
                         [](const ::testing::TestParamInfo<CaptureCounts>& param_info) {
                           std::string name = param_info.param.file;
                           return name.substr(0, name.find('.')).erase(2, 1);
                         });

TEST(Captures, X4Scan1FirstLap) {
  // Walked by hand: the first zero packet is packet 7 (offset 7 + header); lap 0 has 19 packets
  // and 601 samples.
  const auto decoded = decode(profile_for(Model::G6), test::read_file(test::capture("x4-scan1.bin")));
  ASSERT_FALSE(decoded.laps.empty());
  EXPECT_EQ(decoded.laps[0].packets, 19u);
  EXPECT_EQ(decoded.laps[0].points.size(), 601u);
}

TEST(Captures, X4Scan2StartUpLapHoldsNoMoreThanOneTurn) {
  // Walked by hand: lap 1 runs from the zero packet at 348.03 degrees (packet 15) to 180.12 and
  // stays there for 8 packets (the motor settling), then goes on from 0.39 round to 347.66: 540
  // degrees before the next zero packet (packet 69). It is cut at 0.39, where it passes its own
  // start, and packets 40 to 68 are dropped; every other lap of the three captures is one turn.
  const auto decoded = decode(profile_for(Model::G6), test::read_file(test::capture("x4-scan2.bin")));
  ASSERT_GE(decoded.laps.size(), 3u);
  EXPECT_EQ(decoded.laps[0].end, LapEnd::ZeroPacket);
  EXPECT_EQ(decoded.laps[1].end, LapEnd::MissedZeroPacket);
  EXPECT_EQ(decoded.laps[1].packets, 25u);
  EXPECT_FALSE(decoded.laps[1].whole());
  EXPECT_EQ(decoded.laps[2].end, LapEnd::ZeroPacket);
  EXPECT_EQ(decoded.laps[2].index, 2u);
}

TEST(Captures, X4ClassFileWithOneBadChecksum) {
  // 10 junk bytes; zero packet @10 (12 bytes); packet @22 (LSN 40, 351.69 -> 10.23 deg, crosses
  // 360); packet @112 (LSN 34) whose checksum does not match; packet @190 (LSN 40) cut off after
  // 54 of its 90 bytes. The bad packet's 78 bytes are rescanned and hold no other AA 55.
  const Bytes bytes = test::read_file(test::capture("x4class-with-bad-checksum.bin"));
  ASSERT_EQ(bytes.size(), 244u);
  const auto decoded = decode(profile_for(Model::G6), bytes);
  const auto& c = decoded.counters;
  EXPECT_EQ(c.packets, 2u);
  EXPECT_EQ(c.zero_packets, 1u);
  EXPECT_EQ(c.checksum_errors, 1u);
  EXPECT_EQ(c.resync_bytes, 10u + 78u);
  EXPECT_EQ(c.pending_bytes, 54u);
  EXPECT_EQ(c.laps, 0u);  // one zero packet never closes a lap
  EXPECT_TRUE(decoded.laps.empty());
}

TEST(Captures, Tg15PacketAndCutOffFollower) {
  const Bytes bytes = test::read_hex_capture(test::capture("tg15-packet.hex"));
  ASSERT_EQ(bytes.size(), 130u);
  const auto decoded = decode(profile_for(Model::TG15), bytes);
  EXPECT_EQ(decoded.counters.packets, 1u);
  EXPECT_EQ(decoded.counters.checksum_errors, 0u);
  EXPECT_EQ(decoded.counters.resync_bytes, 0u);
  EXPECT_EQ(decoded.counters.pending_bytes, 40u);
  EXPECT_EQ(decoded.counters.zero_packets, 0u);
}

TEST(Captures, X2Packet) {
  const Bytes bytes = test::read_hex_capture(test::capture("x2-packet.hex"));
  const auto decoded = decode(profile_for(Model::G6), bytes);
  EXPECT_EQ(decoded.counters.packets, 1u);
  EXPECT_EQ(decoded.counters.checksum_errors, 0u);
  EXPECT_EQ(decoded.counters.zero_packets, 0u);  // CT 0x86: upper bits set, bit 0 clear
}

}  // namespace
}  // namespace ydscope
