// Properties of the streaming decoder: chunking never changes the result; corruption never
// crashes and never costs a packet it did not touch.
#include <gtest/gtest.h>

#include <algorithm>
#include <random>

#include "core/protocol/byte_access.h"

#include "core/protocol/packet_decoder.h"
#include "protocol_test_support.h"

namespace ydscope {
namespace {

using test::append;
using test::Bytes;
using test::decode;
using test::Decoded;

void expect_same(const Decoded& a, const Decoded& b) {
  ASSERT_EQ(a.laps.size(), b.laps.size());
  for (std::size_t i = 0; i < a.laps.size(); ++i) {
    const Lap& x = a.laps[i];
    const Lap& y = b.laps[i];
    EXPECT_EQ(x.index, y.index);
    EXPECT_EQ(x.packets, y.packets);
    EXPECT_EQ(x.checksum_errors, y.checksum_errors);
    EXPECT_EQ(x.crc, y.crc);
    EXPECT_EQ(x.scan_hz, y.scan_hz);
    EXPECT_EQ(x.health_bits, y.health_bits);
    ASSERT_EQ(x.points.size(), y.points.size()) << "lap " << i;
    for (std::size_t j = 0; j < x.points.size(); ++j) {
      EXPECT_EQ(x.points[j].angle_deg, y.points[j].angle_deg);
      EXPECT_EQ(x.points[j].range_mm, y.points[j].range_mm);
      EXPECT_EQ(x.points[j].flag, y.points[j].flag);
    }
  }
  EXPECT_EQ(a.counters.bytes, b.counters.bytes);
  EXPECT_EQ(a.counters.packets, b.counters.packets);
  EXPECT_EQ(a.counters.zero_packets, b.counters.zero_packets);
  EXPECT_EQ(a.counters.checksum_errors, b.counters.checksum_errors);
  EXPECT_EQ(a.counters.resync_bytes, b.counters.resync_bytes);
  EXPECT_EQ(a.counters.pending_bytes, b.counters.pending_bytes);
  EXPECT_EQ(a.counters.laps, b.counters.laps);
  EXPECT_EQ(a.counters.crc_ok, b.counters.crc_ok);
}

std::vector<std::size_t> random_chunks(std::mt19937& rng, std::size_t count) {
  std::uniform_int_distribution<std::size_t> size(1, 700);
  std::vector<std::size_t> chunks(count);
  for (auto& c : chunks) c = size(rng);
  return chunks;
}

// A stream with junk, a reply header, a bad checksum, G1 LastCRC bytes and a cut-off tail.
Bytes messy_g1_stream() {
  Bytes stream{0xA5, 0x5A, 0x05, 0x00, 0x00, 0x40, 0x81, 0xAA, 0x00, 0xAA};
  test::G1LapSpec spec;
  spec.lsn = 37;
  std::uint8_t crc = 0;
  for (int i = 0; i < 6; ++i) {
    spec.health = static_cast<std::uint8_t>(i);
    crc = test::append_g1_lap(stream, spec, crc);
    if (i == 2) stream[stream.size() - 5] ^= 0x40;  // corrupt the last packet of this lap
  }
  stream.push_back(crc);
  append(stream, test::packet(1, 0, 0, {4}));
  append(stream, Bytes{0xAA, 0x55, 0x00, 0x10, 0x01});  // cut off
  return stream;
}

TEST(DecoderProperty, WholeByteByByteAndRandomChunksAgree) {
  std::mt19937 rng(1234);
  for (const Model model : {Model::G1, Model::G6, Model::TG30}) {
    const auto& profile = profile_for(model);
    const Bytes stream = model == Model::G1 ? messy_g1_stream() : test::synthetic_stream(5, 12, 33);
    const Decoded whole = decode(profile, stream);
    ASSERT_GT(whole.laps.size(), 3u);
    expect_same(whole, decode(profile, stream, {1}));
    for (int round = 0; round < 20; ++round) expect_same(whole, decode(profile, stream, random_chunks(rng, 50)));
  }
}

TEST(DecoderProperty, MessyStreamCountsAreWhatWasBuilt) {
  const Decoded d = decode(profile_for(Model::G1), messy_g1_stream());
  EXPECT_EQ(d.counters.checksum_errors, 1u);
  EXPECT_EQ(d.counters.zero_packets, 7u);
  EXPECT_EQ(d.counters.laps, 6u);
  EXPECT_EQ(d.counters.pending_bytes, 5u);
  ASSERT_EQ(d.laps.size(), 6u);
  EXPECT_EQ(d.laps[2].checksum_errors, 1u);
  EXPECT_EQ(d.laps[2].crc, CrcVerdict::Mismatch);  // a lost packet means a lost CT byte
  EXPECT_EQ(d.counters.crc_ok, 5u);
  EXPECT_EQ(*d.laps[4].health_bits, 4);
}

// Records every packet as (offset in stream, bytes) for the corruption property.
struct Recorder final : PacketSink {
  std::vector<Bytes> packets;
  void on_packet(const PacketView& p) override {
    Bytes b{kPacketHeader0, kPacketHeader1, p.ct, p.lsn};
    b.resize(packet_size(p.lsn));
    write_u16_le(&b[4], p.fsa);
    write_u16_le(&b[6], p.lsa);
    write_u16_le(&b[8], packet_checksum(p.ct, p.lsn, p.fsa, p.lsa, {p.sample_bytes, 2u * p.lsn}));
    std::copy(p.sample_bytes, p.sample_bytes + 2 * p.lsn, b.begin() + 10);
    packets.push_back(std::move(b));
  }
  void on_checksum_error() override {}
};

TEST(DecoderProperty, CorruptionNeverLosesAnUntouchedPacket) {
  std::mt19937 rng(99);
  // Packets with random LSN and samples (including AA and 55 bytes), back to back.
  std::vector<Bytes> originals;
  std::vector<std::size_t> offsets;
  Bytes stream;
  std::uniform_int_distribution<int> lsn_dist(1, 60);
  std::uniform_int_distribution<int> byte_dist(0, 255);
  for (int i = 0; i < 400; ++i) {
    std::vector<std::uint16_t> samples(static_cast<std::size_t>(lsn_dist(rng)));
    for (auto& s : samples) {
      const int pick = byte_dist(rng);
      s = pick < 40 ? 0x55AA : static_cast<std::uint16_t>(pick * 257 + byte_dist(rng));
    }
    offsets.push_back(stream.size());
    originals.push_back(
        test::packet(static_cast<std::uint8_t>(i % 10 == 0), (i % 72) * 5.0, (i % 72) * 5.0 + 4.0, samples));
    append(stream, originals.back());
  }
  for (int round = 0; round < 40; ++round) {
    Bytes damaged = stream;
    std::vector<bool> touched(originals.size(), false);
    std::uniform_int_distribution<std::size_t> where(0, stream.size() - 1);
    const int hits = 1 + round;
    for (int h = 0; h < hits; ++h) {
      const std::size_t at = where(rng);
      damaged[at] = static_cast<std::uint8_t>(damaged[at] ^ (1 + byte_dist(rng) % 255));
      const auto owner = std::upper_bound(offsets.begin(), offsets.end(), at) - offsets.begin() - 1;
      touched[static_cast<std::size_t>(owner)] = true;
    }
    // Also drop a random run of bytes, as a lossy UART does.
    const std::size_t cut = where(rng);
    const std::size_t cut_len = std::min<std::size_t>(1 + byte_dist(rng), damaged.size() - cut);
    damaged.erase(damaged.begin() + static_cast<std::ptrdiff_t>(cut),
                  damaged.begin() + static_cast<std::ptrdiff_t>(cut + cut_len));
    for (std::size_t i = 0; i < originals.size(); ++i)
      if (offsets[i] < cut + cut_len && offsets[i] + originals[i].size() > cut) touched[i] = true;

    PacketDecoder decoder;
    Recorder recorder;
    const auto chunks = random_chunks(rng, 64);
    std::size_t pos = 0;
    for (std::size_t c = 0; pos < damaged.size(); ++c) {
      const std::size_t size = std::min(chunks[c % chunks.size()], damaged.size() - pos);
      decoder.feed({damaged.data() + pos, size}, 0, recorder);
      pos += size;
    }
    decoder.finish(recorder);
    // Every untouched packet appears, in order, among the decoded ones.
    std::size_t found = 0;
    for (std::size_t i = 0; i < originals.size(); ++i) {
      if (touched[i]) continue;
      while (found < recorder.packets.size() && recorder.packets[found] != originals[i]) ++found;
      ASSERT_LT(found, recorder.packets.size()) << "round " << round << " lost untouched packet " << i;
      ++found;
    }
    const auto& c = decoder.counters();
    EXPECT_EQ(c.bytes, c.packet_bytes + c.resync_bytes + c.last_crc_bytes + c.pending_bytes);
  }
}

TEST(DecoderProperty, RandomBytesNeverCrash) {
  std::mt19937 rng(7);
  std::uniform_int_distribution<int> byte_dist(0, 255);
  for (const Model model : {Model::G1, Model::G6}) {
    Bytes noise(200000);
    for (auto& b : noise) {
      const int r = byte_dist(rng);
      b = static_cast<std::uint8_t>(r < 30 ? 0xAA : r < 60 ? 0x55 : r < 70 ? 0x01 : byte_dist(rng));
    }
    const Decoded whole = decode(profile_for(model), noise);
    expect_same(whole, decode(profile_for(model), noise, random_chunks(rng, 100)));
    for (const Lap& lap : whole.laps)
      for (const LapPoint& p : lap.points) {
        ASSERT_GE(p.angle_deg, 0.0f);
        ASSERT_LT(p.angle_deg, 360.0f);
      }
  }
}

}  // namespace
}  // namespace ydscope
