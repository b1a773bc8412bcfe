// X4 and X2 share the G1/G6/TG packet layout: ydscope decodes their bytes as those models (the
// vendor SDK's reading: S/4 mm, corrected at that range) without offering to drive them.
#include <gtest/gtest.h>

#include "core/protocol/scan_decoder.h"
#include "core/protocol/unit_conventions.h"
#include "protocol_test_support.h"

namespace ydscope {
namespace {

using test::Bytes;

std::vector<Lap> decode_as(Model model, const Bytes& bytes, DecoderCounters* counters = nullptr) {
  const ModelProfile& profile = profile_for(model);
  ScanDecoder decoder(profile, conventions_for(profile, std::nullopt, Reading::Field));
  std::vector<Lap> laps;
  decoder.feed(bytes, 0, [&](const Lap& lap) { laps.push_back(lap); });
  if (counters) *counters = decoder.counters();
  return laps;
}

TEST(DecodeOnlyModels, AreFoundForDecodingButNotOfferedToDrive) {
  EXPECT_EQ(all_profiles().size(), 5u);
  EXPECT_EQ(find_profile("X4"), nullptr) << "no session, sim or panel offers an X4";
  ASSERT_NE(find_decodable_profile("x4"), nullptr);
  EXPECT_EQ(find_decodable_profile("x4")->model, Model::X4);
  EXPECT_EQ(find_decodable_profile("X2")->default_baud, 115200u);
  EXPECT_EQ(find_profile_by_code(6), nullptr) << "a unit answering model code 6 is not taken for one we drive";
  EXPECT_EQ(conventions_for(profile_for(Model::X4), std::nullopt, Reading::Field).id, "x4");
  EXPECT_EQ(conventions_for(profile_for(Model::X2), std::nullopt, Reading::Manual).id, "x2");
}

TEST(DecodeOnlyModels, TheRealX4BytesDecodeAsAnX4) {
  const Bytes bytes = test::read_file(test::capture("x4-scan1.bin"));
  DecoderCounters c;
  const auto laps = decode_as(Model::X4, bytes, &c);
  // The counts the independent walk of this file gives (captures_test.cpp).
  EXPECT_EQ(c.packets, 455u);
  EXPECT_EQ(c.checksum_errors, 0u);
  EXPECT_EQ(c.resync_bytes, 7u);
  ASSERT_EQ(laps.size(), 27u);
  EXPECT_EQ(laps[0].points.size(), 601u);
  // S/4 mm, within the X4's rated 0.12-10 m (a few stray far returns aside).
  std::size_t returns = 0, within = 0;
  for (const Lap& lap : laps)
    for (const LapPoint& p : lap.points) {
      if (p.range_mm <= 0.0f) continue;
      ++returns;
      within += p.range_mm >= 100.0f && p.range_mm <= 10'500.0f ? 1 : 0;
    }
  ASSERT_GT(returns, 5000u);
  EXPECT_GT(static_cast<double>(within), 0.99 * static_cast<double>(returns));
}

TEST(DecodeOnlyModels, TheRealX2PacketDecodesAsAnX2) {
  // yato-Neco/ydlidarx2-rs's X2 packet (CT 0x86 on a normal packet), closed into a lap.
  const Bytes packet = test::read_hex_capture(test::capture("x2-packet.hex"));
  Bytes stream = test::packet(0x01, 0.0, 0.0, {0});
  test::append(stream, packet);
  test::append(stream, test::packet(0x01, 0.0, 0.0, {0}));
  DecoderCounters c;
  const auto laps = decode_as(Model::X2, stream, &c);
  EXPECT_EQ(c.checksum_errors, 0u);
  ASSERT_EQ(laps.size(), 1u);
  ASSERT_EQ(laps[0].points.size(), 41u);
  EXPECT_FLOAT_EQ(laps[0].points[1].range_mm, 2362.0f);  // 9448 / 4, as the peer decodes it
  EXPECT_FLOAT_EQ(laps[0].points[9].range_mm, 5866.5f);  // the AA 5B sample inside the payload
}

}  // namespace
}  // namespace ydscope
