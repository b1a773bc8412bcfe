// LineFaults on its own: what each fault does to the bytes handed to it, and what it counts. The
// round-trip tests check the same faults end to end, through a host decoding the stream.
#include "core/sim/line_faults.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <bit>
#include <cstdint>
#include <vector>

#include "core/protocol/commands.h"
#include "core/protocol/scan_packet.h"
#include "sim/sim_test_support.h"

namespace ydscope {
namespace {

using test::kMs;

std::vector<std::uint8_t> packet_of(std::size_t size) {
  std::vector<std::uint8_t> packet(size);
  for (std::size_t i = 0; i < size; ++i) packet[i] = static_cast<std::uint8_t>(i);
  return packet;
}

TEST(LineFaults, WithNoFaultAPacketGoesOutUntouched) {
  LineFaults line({}, 7);
  std::vector<std::uint8_t> packet = packet_of(50);
  const PacketFate fate = line.apply(packet, 10, false, 0);
  EXPECT_FALSE(fate.lost);
  EXPECT_FALSE(fate.corrupted);
  EXPECT_FALSE(fate.altered);
  EXPECT_EQ(packet, packet_of(50));
}

TEST(LineFaults, CorruptionFlipsOnlySampleBytesAndCountsThem) {
  FaultConfig faults;
  faults.corrupt_byte_rate = 1.0;  // every sample byte gets one bit flipped
  LineFaults line(faults, 7);
  const std::vector<std::uint8_t> original = packet_of(50);
  std::vector<std::uint8_t> packet = original;
  const PacketFate fate = line.apply(packet, 10, false, 0);
  EXPECT_FALSE(fate.lost);
  EXPECT_TRUE(std::equal(packet.begin(), packet.begin() + 10, original.begin()));  // the header keeps its framing
  for (std::size_t i = 10; i < packet.size(); ++i) {
    const auto flipped = static_cast<std::uint8_t>(packet[i] ^ original[i]);
    EXPECT_EQ(std::popcount(flipped), 1) << "byte " << i;
  }
  EXPECT_EQ(line.counters().corrupted_bytes, 40u);
  // Whether 40 flips cancel in the XOR checksum decides corrupted against altered, never both.
  EXPECT_NE(fate.corrupted, fate.altered);
  EXPECT_EQ(line.counters().corrupted_packets, fate.corrupted ? 1u : 0u);
}

TEST(LineFaults, TheZeroPacketIsNeverLostButOthersAre) {
  FaultConfig faults;
  faults.lost_packet_rate = 1.0;
  LineFaults line(faults, 7);
  std::vector<std::uint8_t> packet = packet_of(20);
  EXPECT_FALSE(line.apply(packet, 10, true, 0).lost);
  EXPECT_TRUE(line.apply(packet, 10, false, 0).lost);
  EXPECT_EQ(line.counters().lost_packets, 1u);
}

TEST(LineFaults, AStallDiscardsPacketsAndRepliesInsideItsWindowOnly) {
  LineFaults line({}, 7);
  line.stall(100 * kMs, 50 * kMs);
  EXPECT_EQ(line.counters().stalls, 1u);
  std::vector<std::uint8_t> packet = packet_of(30);
  EXPECT_FALSE(line.apply(packet, 10, false, 99 * kMs).lost);
  EXPECT_TRUE(line.apply(packet, 10, true, 100 * kMs).lost);  // even the zero packet
  EXPECT_FALSE(line.apply(packet, 10, false, 150 * kMs).lost);
  EXPECT_EQ(line.counters().stalled_packets, 1u);

  const std::vector<std::uint8_t> reply = {0xA5, 0x5A, 0x03, 0x00, 0x00, 0x00, 0x06};
  std::vector<std::uint8_t> out = {1, 2};
  EXPECT_FALSE(line.frame_reply(reply, 120 * kMs, out));
  EXPECT_EQ(out, (std::vector<std::uint8_t>{1, 2}));  // nothing appended
  EXPECT_EQ(line.counters().stalled_bytes, 30u + reply.size());
  EXPECT_TRUE(line.frame_reply(reply, 160 * kMs, out));
  EXPECT_EQ(out.size(), 2u + reply.size());
}

TEST(LineFaults, JunkBeforeAReplyNeverLooksLikeAStart) {
  FaultConfig faults;
  faults.junk_before_reply = 500;
  LineFaults line(faults, 3);
  const std::vector<std::uint8_t> reply = {0xA5, 0x5A, 0x01, 0x00, 0x00, 0x00, 0x04, 0x00};
  std::vector<std::uint8_t> out;
  ASSERT_TRUE(line.frame_reply(reply, 0, out));
  ASSERT_EQ(out.size(), 500u + reply.size());
  EXPECT_TRUE(std::none_of(out.begin(), out.begin() + 500,
                           [](std::uint8_t b) { return b == kCommandStart || b == kPacketHeader0; }));
  EXPECT_TRUE(std::equal(reply.begin(), reply.end(), out.begin() + 500));
  EXPECT_EQ(line.counters().junk_bytes, 500u);
}

TEST(LineFaults, DroppedBytesPullTheZeroPacketEndsBack) {
  FaultConfig faults;
  faults.drop_byte_rate = 0.3;
  LineFaults line(faults, 11);
  // Bytes 1..200 after a prefix the call must leave alone; a zero packet ends after byte 100 and after byte 200.
  std::vector<std::uint8_t> out = {0xEE, 0xEE};
  for (int i = 1; i <= 200; ++i) out.push_back(static_cast<std::uint8_t>(i));
  std::vector<std::size_t> zero_ends = {999, 102, 202};
  line.drop_bytes(out, 2, &zero_ends, 1);

  const std::uint64_t dropped = line.counters().dropped_bytes;
  EXPECT_GT(dropped, 20u);
  EXPECT_LT(dropped, 100u);
  ASSERT_EQ(out.size(), 202u - dropped);
  EXPECT_EQ(out[0], 0xEE);
  EXPECT_EQ(out[1], 0xEE);
  EXPECT_TRUE(std::is_sorted(out.begin() + 2, out.end()));  // what is left keeps its order
  EXPECT_EQ(zero_ends[0], 999u);                            // before zero_base: untouched
  EXPECT_EQ(zero_ends[2], out.size());                      // the last byte's end is the end
  // The first end sits just past the kept bytes numbered up to 100.
  const auto kept_to_100 = std::count_if(out.begin() + 2, out.end(), [](std::uint8_t b) { return b <= 100; });
  EXPECT_EQ(zero_ends[1], 2u + static_cast<std::size_t>(kept_to_100));
}

TEST(LineFaults, PeriodicStallsComeOnScheduleWhileArmed) {
  FaultConfig faults;
  faults.stall_ms = 20;
  faults.stall_every_ms = 1000;
  LineFaults line(faults, 7);
  EXPECT_EQ(line.next_periodic_stall_ns(), LineFaults::kNever);  // not before a scan arms them
  line.arm_periodic_stalls(5 * kMs);
  EXPECT_EQ(line.next_periodic_stall_ns(), 1005 * kMs);
  EXPECT_FALSE(line.take_due_stall(1004 * kMs));
  EXPECT_EQ(line.take_due_stall(1005 * kMs), 1005 * kMs);
  EXPECT_EQ(line.next_periodic_stall_ns(), 2005 * kMs);
  line.disarm_periodic_stalls();
  EXPECT_FALSE(line.take_due_stall(5000 * kMs));

  FaultConfig off;
  line.set_config(off, 0);  // scanning, but no stall configured
  EXPECT_EQ(line.next_periodic_stall_ns(), LineFaults::kNever);
}

}  // namespace
}  // namespace ydscope
