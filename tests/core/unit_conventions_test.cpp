// The conventions table row by row (docs/conventions.md gives each value's source), the firmware
// byte order it is chosen by, and what each row does to decoded bytes: scale, correction, the
// scan rate in a zero packet's CT and the byte real TG units send before it.
#include <gtest/gtest.h>

#include <cmath>

#include "core/protocol/angle_correction.h"
#include "core/protocol/scan_decoder.h"
#include "core/protocol/unit_conventions.h"
#include "protocol_test_support.h"

namespace ydscope {
namespace {

using test::Bytes;

struct RowCase {
  Model model;
  std::optional<FirmwareVersion> firmware;  // the SDK's byte order
  Reading reading;
  const char* id;
  double scale;
  bool correction;
  std::uint16_t samples_khz[3];  // at ranging codes 4, 8, 9 kHz (G1: 4, 5, 8)
  bool ct_rate;
  double ct_offset_hz;
  ByteBeforeZero byte;
};

class ConventionRow : public ::testing::TestWithParam<RowCase> {};

TEST_P(ConventionRow, HoldsItsValues) {
  const RowCase& c = GetParam();
  const ModelProfile& profile = profile_for(c.model);
  const UnitConventions& conventions = conventions_for(profile, c.firmware, c.reading);
  EXPECT_EQ(conventions.id, c.id);
  EXPECT_DOUBLE_EQ(conventions.distance_scale, c.scale);
  EXPECT_EQ(conventions.angle_correction, c.correction);
  for (std::size_t code = 0; code < 3; ++code)
    EXPECT_EQ(conventions.samples_per_s(profile, profile.ranging_khz[code]), c.samples_khz[code] * 1000.0)
        << "code " << code;
  EXPECT_EQ(conventions.zero_packet_scan_rate.present, c.ct_rate);
  EXPECT_DOUBLE_EQ(conventions.zero_packet_scan_rate.offset_hz, c.ct_offset_hz);
  EXPECT_EQ(conventions.byte_before_zero, c.byte);
  EXPECT_EQ(find_conventions(conventions.id), &conventions) << "a recording names the row by its id";
  EXPECT_TRUE(conventions_fit(conventions, profile));
}

constexpr FirmwareVersion kOld{1, 2};  // the vendor SDK's isOldVersionTOFLidar: major <= 1, minor <= 2
constexpr FirmwareVersion kNew{1, 3};

INSTANTIATE_TEST_SUITE_P(
    Table, ConventionRow,
    ::testing::Values(
        RowCase{Model::G1, std::nullopt, Reading::Field, "g1", 1.0, true, {4, 5, 8}, false, 0, ByteBeforeZero::LapCrc8},
        RowCase{
            Model::G1, std::nullopt, Reading::Manual, "g1", 1.0, true, {4, 5, 8}, false, 0, ByteBeforeZero::LapCrc8},
        RowCase{
            Model::G6, std::nullopt, Reading::Field, "g6-field", 0.5, true, {8, 16, 18}, true, 0, ByteBeforeZero::None},
        RowCase{Model::G6,
                std::nullopt,
                Reading::Manual,
                "g6-manual",
                0.25,
                true,
                {4, 8, 9},
                false,
                0,
                ByteBeforeZero::None},
        RowCase{Model::TG30,
                kNew,
                Reading::Field,
                "tg-field",
                1.0,
                false,
                {10, 18, 20},
                true,
                3.0,
                ByteBeforeZero::Unexplained},
        RowCase{Model::TG15,
                std::nullopt,
                Reading::Field,
                "tg-field",
                1.0,
                false,
                {10, 18, 20},
                true,
                3.0,
                ByteBeforeZero::Unexplained},
        RowCase{Model::TG50,
                kOld,
                Reading::Field,
                "tg-field-fw1.2",
                0.5,
                false,
                {10, 18, 20},
                true,
                0,
                ByteBeforeZero::Unexplained},
        RowCase{Model::TG30, kNew, Reading::Manual, "tg-manual", 0.5, true, {4, 8, 9}, false, 0, ByteBeforeZero::None}),
    [](const auto& test_case) {
      std::string name = std::string(test_case.param.id) + "_" + std::to_string(test_case.index);
      for (char& c : name)
        if (c == '-' || c == '.') c = '_';
      return name;
    });

TEST(Conventions, FirmwareIsReadInTheVendorSdksByteOrder) {
  // A5 90's bytes 1 and 2: the manuals call the first the major version, the SDK (whose TG rule
  // is written in its own order) the second. 2.1 by the manual is 1.2 to the SDK: old firmware.
  const FirmwareVersion v = firmware_as_sdk_reads(2, 1);
  EXPECT_EQ(v.major, 1);
  EXPECT_EQ(v.minor, 2);
  EXPECT_EQ(conventions_for(profile_for(Model::TG30), v, Reading::Field).id, "tg-field-fw1.2");
  EXPECT_EQ(conventions_for(profile_for(Model::TG30), firmware_as_sdk_reads(1, 2), Reading::Field).id, "tg-field");
}

TEST(Conventions, ARowOfAnotherFamilyDoesNotFit) {
  EXPECT_FALSE(conventions_fit(*find_conventions("g6-field"), profile_for(Model::TG30)));
  EXPECT_FALSE(conventions_fit(*find_conventions("tg-field"), profile_for(Model::G6)));
  EXPECT_EQ(find_conventions("g7-field"), nullptr);
}

TEST(Conventions, ReadingsParseByName) {
  EXPECT_EQ(parse_reading("field"), Reading::Field);
  EXPECT_EQ(parse_reading("manual"), Reading::Manual);
  EXPECT_FALSE(parse_reading("sdk").has_value());
  EXPECT_EQ(reading_name(Reading::Manual), "manual");
}

// One lap (zero packet + one packet of two samples) closed by the next zero packet.
Bytes two_zero_packets(std::uint8_t zero_ct, std::uint16_t sample, std::optional<std::uint8_t> byte_before_zero) {
  Bytes out;
  test::append(out, test::packet(zero_ct, 0.0, 0.0, {sample}));
  test::append(out, test::packet(0x00, 100.0, 110.0, {sample, sample}));
  if (byte_before_zero) out.push_back(*byte_before_zero);
  test::append(out, test::packet(zero_ct, 0.0, 0.0, {sample}));
  return out;
}

std::vector<Lap> decode_with(const UnitConventions& conventions, Model model, const Bytes& bytes,
                             DecoderCounters* counters = nullptr) {
  ScanDecoder decoder(profile_for(model), conventions);
  std::vector<Lap> laps;
  decoder.feed(bytes, 0, [&](const Lap& lap) { laps.push_back(lap); });
  if (counters) *counters = decoder.counters();
  return laps;
}

TEST(Conventions, AG6ReadAsTheFieldReadsItIsAtHalfAMillimetrePerCountCorrectedAtThatRange) {
  const UnitConventions& field = *find_conventions("g6-field");
  const std::uint16_t raw = 8000;  // 4 m as the field reads it; 2 m by the manual
  const auto laps = decode_with(field, Model::G6, two_zero_packets(0x01, raw, std::nullopt));
  ASSERT_EQ(laps.size(), 1u);
  const LapPoint& p = laps[0].points[1];
  EXPECT_FLOAT_EQ(p.range_mm, 4000.0f);
  EXPECT_NEAR(p.angle_deg, normalize_degrees(100.0 + angle_correction_deg(4000.0)), 1e-4);
  const auto manual = decode_with(*find_conventions("g6-manual"), Model::G6, two_zero_packets(0x01, raw, std::nullopt));
  EXPECT_FLOAT_EQ(manual[0].points[1].range_mm, 2000.0f) << "the manual's reading is unchanged";
  EXPECT_NEAR(manual[0].points[1].angle_deg, normalize_degrees(100.0 + angle_correction_deg(2000.0)), 1e-4);
}

TEST(Conventions, AG6ZeroPacketCarriesItsScanRateInTheFieldReading) {
  const std::uint8_t ct = static_cast<std::uint8_t>(82 << 1 | 1);  // 8.2 Hz
  const auto field = decode_with(*find_conventions("g6-field"), Model::G6, two_zero_packets(ct, 4000, std::nullopt));
  ASSERT_EQ(field.size(), 1u);
  ASSERT_TRUE(field[0].scan_hz.has_value());
  EXPECT_NEAR(*field[0].scan_hz, 8.2, 1e-9);
  const auto manual = decode_with(*find_conventions("g6-manual"), Model::G6, two_zero_packets(ct, 4000, std::nullopt));
  EXPECT_FALSE(manual[0].scan_hz.has_value()) << "the G6 manual gives CT no meaning beyond bit 0";
}

TEST(Conventions, ATgOnCurrentFirmwareIsRawMillimetresUncorrectedWithItsScanRateFrom3Hz) {
  const std::uint8_t ct = static_cast<std::uint8_t>(70 << 1 | 1);  // 7.0 + 3 = 10 Hz
  DecoderCounters counters;
  const auto laps = decode_with(*find_conventions("tg-field"), Model::TG30,
                                two_zero_packets(ct, 2461, std::uint8_t{0x5C}), &counters);
  ASSERT_EQ(laps.size(), 1u);
  EXPECT_FLOAT_EQ(laps[0].points[1].range_mm, 2461.0f);
  EXPECT_NEAR(laps[0].points[1].angle_deg, 100.0, 1e-4) << "a time-of-flight unit needs no triangulation correction";
  EXPECT_FALSE(laps[0].angles_corrected);
  ASSERT_TRUE(laps[0].scan_hz.has_value());
  EXPECT_NEAR(*laps[0].scan_hz, 10.0, 1e-9);
  // The byte before the zero packet is understood: not link noise.
  EXPECT_EQ(counters.resync_bytes, 0u);
  EXPECT_EQ(counters.checksum_errors, 0u);
  EXPECT_EQ(laps[0].crc, CrcVerdict::NotApplicable) << "its meaning is not documented: nothing to check";
}

TEST(Conventions, TheManualsReadingCountsTheTgBytesBeforeZeroAsNoise) {
  DecoderCounters counters;
  decode_with(*find_conventions("tg-manual"), Model::TG30, two_zero_packets(0x01, 2461, std::uint8_t{0x5C}), &counters);
  EXPECT_EQ(counters.resync_bytes, 1u);
}

TEST(Conventions, TheRealTg15PacketReadsAsRangesOfAboutTwoAndAHalfMetres) {
  // tier4/ydlidar_driver's TG15 bytes (tests/data/captures): the peer decodes them as raw mm.
  const Bytes bytes = test::read_hex_capture(test::capture("tg15-packet.hex"));
  Bytes stream;
  test::append(stream, test::packet(0x01, 0.0, 0.0, {1000}));
  test::append(stream, Bytes(bytes.begin(), bytes.begin() + 90));  // the whole LSN=40 packet
  test::append(stream, test::packet(0x01, 0.0, 0.0, {1000}));
  const auto laps = decode_with(*find_conventions("tg-field"), Model::TG15, stream);
  ASSERT_EQ(laps.size(), 1u);
  ASSERT_EQ(laps[0].points.size(), 41u);
  EXPECT_FLOAT_EQ(laps[0].points[1].range_mm, 2461.0f);  // the first sample, 0x099D
}

}  // namespace
}  // namespace ydscope
