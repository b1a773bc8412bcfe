// PacketDecoder: header hunting, check bits, checksum, one-byte resync, split packets, LastCRC.
#include <gtest/gtest.h>

#include "core/protocol/packet_decoder.h"
#include "protocol_test_support.h"

namespace ydscope {
namespace {

using test::append;
using test::Bytes;
using test::packet;

struct Collected final : PacketSink {
  struct Seen {
    std::uint8_t ct, lsn;
    std::uint16_t fsa, lsa;
    std::vector<std::uint16_t> samples;
    std::optional<std::uint8_t> last_crc;
  };
  std::vector<Seen> packets;
  int checksum_errors = 0;
  void on_packet(const PacketView& p) override {
    Seen seen{p.ct, p.lsn, p.fsa, p.lsa, {}, p.last_crc};
    for (std::size_t i = 0; i < p.lsn; ++i) seen.samples.push_back(p.sample(i));
    packets.push_back(seen);
  }
  void on_checksum_error() override { ++checksum_errors; }
};

void expect_accounting(const PacketCounters& c) {
  EXPECT_EQ(c.bytes, c.packet_bytes + c.resync_bytes + c.last_crc_bytes + c.pending_bytes);
}

TEST(PacketDecoder, FindsPacketsBetweenJunk) {
  Bytes stream{0x00, 0x12, 0xA5, 0x5A, 0x05, 0x00, 0x00, 0x40, 0x81};  // junk and a scan reply header
  append(stream, packet(1, 0.0, 0.0, {7}));
  append(stream, Bytes{0x55, 0xAA});
  append(stream, packet(0, 10.0, 20.0, {1, 2, 3}));
  PacketDecoder decoder;
  Collected sink;
  decoder.feed(stream, 0, sink);
  ASSERT_EQ(sink.packets.size(), 2u);
  EXPECT_EQ(sink.packets[0].ct, 1);
  EXPECT_EQ(sink.packets[0].samples, std::vector<std::uint16_t>{7});
  EXPECT_FALSE(sink.packets[0].last_crc);  // not G1
  EXPECT_EQ(sink.packets[1].samples, (std::vector<std::uint16_t>{1, 2, 3}));
  EXPECT_EQ(decoder.counters().resync_bytes, 11u);
  EXPECT_EQ(decoder.counters().packets, 2u);
  EXPECT_EQ(decoder.counters().zero_packets, 1u);
  expect_accounting(decoder.counters());
}

TEST(PacketDecoder, HeaderAtTheSecondAaOfAaAa55) {
  Bytes stream{0xAA};
  append(stream, packet(0, 10.0, 20.0, {5}));
  PacketDecoder decoder;
  Collected sink;
  decoder.feed(stream, 0, sink);
  ASSERT_EQ(sink.packets.size(), 1u);
  EXPECT_EQ(decoder.counters().resync_bytes, 1u);
  // The same split after the first AA.
  PacketDecoder split;
  Collected split_sink;
  split.feed({stream.data(), 1}, 0, split_sink);
  split.feed({stream.data() + 1, stream.size() - 1}, 0, split_sink);
  ASSERT_EQ(split_sink.packets.size(), 1u);
  EXPECT_EQ(split.counters().resync_bytes, 1u);
}

TEST(PacketDecoder, CheckBitsMustBeSet) {
  Bytes bad = packet(0, 10.0, 20.0, {5});
  bad[4] &= 0xFE;  // FSA check bit cleared
  Bytes stream = bad;
  append(stream, packet(0, 10.0, 20.0, {6}));
  PacketDecoder decoder;
  Collected sink;
  decoder.feed(stream, 0, sink);
  ASSERT_EQ(sink.packets.size(), 1u);
  EXPECT_EQ(sink.packets[0].samples[0], 6);
  EXPECT_EQ(sink.checksum_errors, 0);  // a bad header is not a checksum error
  EXPECT_EQ(decoder.counters().resync_bytes, bad.size());
}

TEST(PacketDecoder, BadChecksumResyncsOneByteAndFindsAPacketInside) {
  // A packet truncated in transit: its header claims 20 samples, but only 2 arrived before the
  // next packet. The checksum fails, and the packet hidden in the claimed length is still found.
  // (Distinct samples: a whole valid packet XORs to zero, so identical missing samples would let
  // the truncated packet's checksum pass by construction.)
  std::vector<std::uint16_t> claimed(20);
  for (std::size_t i = 0; i < claimed.size(); ++i) claimed[i] = static_cast<std::uint16_t>(0x1111 + 3 * i);
  Bytes truncated = packet(0, 10.0, 20.0, claimed);
  truncated.resize(14);
  Bytes stream = truncated;
  append(stream, packet(0, 30.0, 40.0, {0x2222, 0x3333}));
  append(stream, Bytes(40, 0x00));
  PacketDecoder decoder;
  Collected sink;
  decoder.feed(stream, 0, sink);
  ASSERT_EQ(sink.packets.size(), 1u);
  EXPECT_EQ(sink.packets[0].samples, (std::vector<std::uint16_t>{0x2222, 0x3333}));
  EXPECT_EQ(sink.checksum_errors, 1);
  EXPECT_EQ(decoder.counters().checksum_errors, 1u);
  expect_accounting(decoder.counters());
}

TEST(PacketDecoder, AaInsideSamplesIsNotAHeader) {
  // The X2 capture's samples hold AA 5B; a sample pair AA 55 must not break the packet either.
  const Bytes stream = packet(0, 10.0, 20.0, {0x5BAA, 0x55AA, 0xAAAA});
  PacketDecoder decoder;
  Collected sink;
  decoder.feed(stream, 0, sink);
  ASSERT_EQ(sink.packets.size(), 1u);
  EXPECT_EQ(decoder.counters().resync_bytes, 0u);
}

TEST(PacketDecoder, CutOffPacketIsPendingNotEmitted) {
  Bytes stream = packet(1, 0.0, 0.0, {1});
  Bytes cut = packet(0, 10.0, 20.0, {1, 2, 3, 4});
  cut.resize(cut.size() - 3);
  append(stream, cut);
  PacketDecoder decoder;
  Collected sink;
  decoder.feed(stream, 0, sink);
  EXPECT_EQ(sink.packets.size(), 1u);
  EXPECT_EQ(decoder.counters().pending_bytes, cut.size());
  expect_accounting(decoder.counters());
  decoder.reset();
  EXPECT_EQ(decoder.counters().bytes, 0u);
  EXPECT_EQ(decoder.counters().pending_bytes, 0u);
}

TEST(PacketDecoder, FinishFreesPacketsBehindAFalseStartAtTheEnd) {
  // A false AA 55 claiming 200 samples, then two real packets and the end of the stream.
  Bytes stream{0xAA, 0x55, 0x00, 200, 0x01, 0x00, 0x01, 0x00, 0x00, 0x00};
  append(stream, packet(0, 10.0, 20.0, {1}));
  append(stream, packet(0, 30.0, 40.0, {2}));
  Bytes cut = packet(0, 50.0, 60.0, {3, 4, 5});
  cut.resize(12);
  append(stream, cut);
  PacketDecoder decoder;
  Collected sink;
  decoder.feed(stream, 0, sink);
  EXPECT_TRUE(sink.packets.empty());  // still waiting: the false start might be real
  decoder.finish(sink);
  ASSERT_EQ(sink.packets.size(), 2u);
  EXPECT_EQ(sink.packets[1].samples[0], 2);
  EXPECT_EQ(decoder.counters().resync_bytes, 10u);
  EXPECT_EQ(decoder.counters().pending_bytes, 12u);  // the real cut-off packet stays pending
  expect_accounting(decoder.counters());
}

TEST(PacketDecoder, MaximumPacketSplitAnywhere) {
  const Bytes stream = packet(0, 10.0, 20.0, std::vector<std::uint16_t>(255, 0xABCD));
  ASSERT_EQ(stream.size(), kMaxPacketSize);
  for (std::size_t cut = 1; cut < stream.size(); ++cut) {
    PacketDecoder decoder;
    Collected sink;
    decoder.feed({stream.data(), cut}, 0, sink);
    decoder.feed({stream.data() + cut, stream.size() - cut}, 0, sink);
    ASSERT_EQ(sink.packets.size(), 1u) << cut;
    EXPECT_EQ(sink.packets[0].samples.size(), 255u);
  }
}

TEST(PacketDecoder, G1LastCrcByteBeforeZeroPackets) {
  Bytes stream{0x7E};
  append(stream, packet(1, 0.0, 0.0, {4}));
  append(stream, packet(0, 10.0, 20.0, {4}));
  stream.push_back(0xAA);  // a LastCRC that happens to be AA
  append(stream, packet(1, 0.0, 0.0, {4}));
  append(stream, packet(1, 0.0, 0.0, {4}));  // no LastCRC byte: none reported
  PacketDecoder decoder(true);
  Collected sink;
  decoder.feed(stream, 0, sink);
  ASSERT_EQ(sink.packets.size(), 4u);
  EXPECT_EQ(sink.packets[0].last_crc, 0x7E);
  EXPECT_FALSE(sink.packets[1].last_crc);
  EXPECT_EQ(sink.packets[2].last_crc, 0xAA);
  EXPECT_FALSE(sink.packets[3].last_crc);
  EXPECT_EQ(decoder.counters().resync_bytes, 0u);
  EXPECT_EQ(decoder.counters().last_crc_bytes, 2u);
  expect_accounting(decoder.counters());
}

TEST(PacketDecoder, RealX2PacketWithAa5bInsideAndUpperCtBits) {
  const Bytes bytes = test::read_hex_capture(test::capture("x2-packet.hex"));
  ASSERT_EQ(bytes.size(), 90u);
  PacketDecoder decoder;
  Collected sink;
  decoder.feed(bytes, 0, sink);
  ASSERT_EQ(sink.packets.size(), 1u);
  EXPECT_EQ(sink.packets[0].ct, 0x86);  // not a lap start: bit 0 is 0
  EXPECT_EQ(sink.packets[0].lsn, 40);
  EXPECT_EQ(sink.packets[0].fsa, 0x70ED);
  EXPECT_EQ(sink.packets[0].samples[8], 0x5BAA);
  EXPECT_EQ(decoder.counters().zero_packets, 0u);
  EXPECT_EQ(decoder.counters().resync_bytes, 0u);
}

}  // namespace
}  // namespace ydscope
