// Scan packet layout, XOR checksum, raw angles and samples, G1 CT information and its CRC8.
#include <gtest/gtest.h>

#include <string_view>

#include "core/protocol/byte_access.h"
#include "core/protocol/g1_ct.h"
#include "core/protocol/scan_packet.h"
#include "protocol_test_support.h"

namespace ydscope {
namespace {

using test::Bytes;

TEST(ScanPacket, EncodesLayoutAndChecksum) {
  const std::uint16_t samples[] = {0x6FE4, 0x0102};
  Bytes out(packet_size(2));
  ASSERT_EQ(encode_scan_packet({0x00, 0x6FE5, 0x79BD, samples}, out), 14u);
  EXPECT_EQ(out[0], 0xAA);
  EXPECT_EQ(out[1], 0x55);
  EXPECT_EQ(out[2], 0x00);
  EXPECT_EQ(out[3], 2);
  EXPECT_EQ(out[4], 0xE5);
  EXPECT_EQ(out[5], 0x6F);
  EXPECT_EQ(out[6], 0xBD);
  EXPECT_EQ(out[7], 0x79);
  // CS = 0x55AA ^ (CT | LSN<<8) ^ FSA ^ LSA ^ S1 ^ S2, computed by hand:
  // 0x55AA ^ 0x0200 = 0x57AA; ^0x6FE5 = 0x384F; ^0x79BD = 0x41F2; ^0x6FE4 = 0x2E16; ^0x0102 = 0x2F14
  EXPECT_EQ(out[8], 0x14);
  EXPECT_EQ(out[9], 0x2F);
  EXPECT_EQ(out[10], 0xE4);
  EXPECT_EQ(out[11], 0x6F);
  Bytes too_small(13);
  EXPECT_EQ(encode_scan_packet({0, 1, 1, samples}, too_small), 0u);
}

TEST(ScanPacket, ChecksumMatchesRealTg15Packet) {
  const Bytes bytes = test::read_hex_capture(test::capture("tg15-packet.hex"));
  ASSERT_GE(bytes.size(), 90u);
  const std::uint8_t lsn = bytes[3];
  ASSERT_EQ(lsn, 40);
  const std::uint16_t cs =
      packet_checksum(bytes[2], lsn, read_u16_le(&bytes[4]), read_u16_le(&bytes[6]), {bytes.data() + 10, 2u * lsn});
  EXPECT_EQ(cs, 0x7834);  // the CS field of the captured packet
}

TEST(ScanPacket, RawAngles) {
  // The manuals' example: FSA = 0x6FE5 -> 223.78 deg, LSA = 0x79BD -> 243.47 deg.
  EXPECT_NEAR(raw_angle_degrees(0x6FE5), 223.78, 0.005);
  EXPECT_NEAR(raw_angle_degrees(0x79BD), 243.47, 0.005);
  EXPECT_EQ(raw_angle_degrees(0x6FE5), 14322 / 64.0);
  EXPECT_TRUE(angle_check_bit_ok(0x6FE5));
  EXPECT_FALSE(angle_check_bit_ok(0x6FE4));
  EXPECT_EQ(encode_raw_angle(14322 / 64.0), 0x6FE5);
  EXPECT_EQ(encode_raw_angle(360.0), 0x0001);
  EXPECT_EQ(encode_raw_angle(-1.0), ((359 * 64) << 1) | 1);
}

TEST(ScanPacket, SampleEncodingPerModelFormula) {
  // G1: S>>2 mm with the flag in S&3: E4 6F (0x6FE4) is 7161 mm, flag 0.
  EXPECT_EQ(encode_sample(7161, PointFlag::None, 2, 1.0), 0x6FE4);
  EXPECT_EQ(encode_sample(7161, PointFlag::AmbientLight, 2, 1.0), 0x6FE7);
  // G6: S/4: E5 6F is 7161.25 mm. TG: S/2: the same word is 14322.5 mm.
  EXPECT_EQ(encode_sample(7161.25, PointFlag::None, 0, 0.25), 0x6FE5);
  EXPECT_EQ(encode_sample(14322.5, PointFlag::Specular, 0, 0.5), 0x6FE5);  // no flag bits: flag dropped
  EXPECT_EQ(encode_sample(1e9, PointFlag::None, 2, 1.0), 0xFFFC);          // saturates
  EXPECT_EQ(encode_sample(-5, PointFlag::None, 0, 0.25), 0);
}

TEST(G1Ct, Crc8IsTheReflected0x8CCrc) {
  // Reflected poly 0x8C with init 0 and no final XOR is the catalogued CRC-8/MAXIM, whose check
  // value over "123456789" is 0xA1.
  constexpr std::string_view check = "123456789";
  std::uint8_t crc = 0;
  for (char c : check) crc = ct_crc8_update(crc, static_cast<std::uint8_t>(c));
  EXPECT_EQ(crc, 0xA1);
  // One step worked by hand: 0x01 shifts out ones at steps 1, 4, 5 and 7 -> 0x5E.
  EXPECT_EQ(ct_crc8_update(0, 0x01), 0x5E);
  EXPECT_EQ(ct_crc8_update(0, 0x00), 0x00);
  const std::uint8_t cts[] = {0x01, 0x00};
  EXPECT_EQ(ct_crc8(cts), ct_crc8_update(0x5E, 0x00));
  // The manual's loop: a lap of a zero packet at 9 Hz (CT 0xB5), version 1.2, two more packets.
  const std::uint8_t lap[] = {0xB5, 0x44, 0x00, 0x00};
  std::uint8_t manual = 0;
  for (std::uint8_t ct : lap) manual = ct_crc8_update(manual, ct);
  EXPECT_EQ(ct_crc8(lap), manual);
}

TEST(G1Ct, InformationFields) {
  // Zero packet CT = (Freq*10)<<1 | 1: 9.0 Hz -> 0xB5.
  EXPECT_EQ(g1_zero_packet_ct(9.0), 0xB5);
  EXPECT_DOUBLE_EQ(g1_ct_scan_hz(0xB5), 9.0);
  // Index 1: CT = (Major<<6) + (Minor<<1).
  EXPECT_EQ(g1_version_ct(1, 2), 0x44);
  EXPECT_EQ(g1_ct_version_major(0x44), 1);
  EXPECT_EQ(g1_ct_version_minor(0x44), 2);
  // Index 3: CT = Health<<1.
  EXPECT_EQ(g1_health_ct(0x21), 0x42);
  EXPECT_EQ(g1_ct_health(0x42), 0x21);
}

}  // namespace
}  // namespace ydscope
