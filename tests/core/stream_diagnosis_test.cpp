// StreamDiagnosis: the sentence for bytes that make no packets, each verdict from bytes: real X4
// and X2 captures, T-mini Pro packets (tier4/ydlidar_driver's test vectors), a G6 stream read at
// the wrong baud (its UART bit stream resampled), damaged packets, replies only, and healthy streams.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "core/protocol/byte_access.h"
#include "core/protocol/stream_diagnosis.h"
#include "protocol_test_support.h"
#include "support/uart_line.h"

namespace ydscope {
namespace {

using test::Bytes;

::testing::AssertionResult has(const std::string& text, const std::string& part) {
  if (text.find(part) != std::string::npos) return ::testing::AssertionSuccess();
  return ::testing::AssertionFailure() << "\"" << part << "\" is not in \"" << text << "\"";
}

// Feeds `bytes` in chunks as a device emitting `bytes_per_s` would deliver them (0: no times).
StreamDiagnosis fed(const Bytes& bytes, double bytes_per_s = 0, std::size_t chunk = 256) {
  StreamDiagnosis d;
  for (std::size_t at = 0; at < bytes.size(); at += chunk) {
    const std::size_t n = std::min(chunk, bytes.size() - at);
    const auto rx_ns =
        bytes_per_s > 0 ? static_cast<std::int64_t>(1e9 + static_cast<double>(at + n) * 1e9 / bytes_per_s) : 0;
    d.feed({bytes.data() + at, n}, rx_ns);
  }
  return d;
}

Bytes repeated(const Bytes& unit, std::size_t at_least) {
  Bytes out;
  while (out.size() < at_least) test::append(out, unit);
  return out;
}

std::string verdict_of(const StreamDiagnosis& d, Model model, std::uint32_t baud) {
  return d.verdict(profile_for(model), baud).value_or("(no verdict)");
}

// ---- 2-byte samples: real X4 and X2 bytes -----------------------------------------------------

// The X4 capture holds 16 721 samples in 38 074 bytes (2.28 bytes a sample); an X4 sends 5 k
// samples/s, so 11 400 bytes/s.
constexpr double kX4BytesPerS = 11400;

TEST(StreamDiagnosis, X4BytesNameTheX4FamilyByRateWhenATg30WasExpected) {
  const Bytes bytes = test::read_file(test::capture("x4-scan1.bin"));
  const StreamDiagnosis d = fed(bytes, kX4BytesPerS);
  const StreamFindings f = d.findings();
  EXPECT_EQ(f.window_bytes, StreamDiagnosis::kWindowBytes);
  EXPECT_GT(f.two_byte_packets, 80u);
  EXPECT_EQ(f.two_byte_max_lsn, 40);
  EXPECT_EQ(f.three_byte_packets, 0u);
  ASSERT_TRUE(f.bytes_per_s);
  EXPECT_NEAR(*f.bytes_per_s, kX4BytesPerS, 1);
  const std::string v = verdict_of(d, Model::TG30, 512000);
  // The window's last 8 KiB run a little below the file's average: 4.9 k.
  EXPECT_TRUE(has(v, "verify as 2-byte samples (LSN up to 40, about 4.9 k samples/s)"));
  EXPECT_TRUE(has(v, "X4 (model code 6, 128000 baud, 5 k samples/s)"));
  EXPECT_TRUE(has(v, "not a TG30 (10-20 k samples/s at 512000 baud)"));
  EXPECT_TRUE(has(v, "try --model G6"));
}

TEST(StreamDiagnosis, X4BytesAtTheX4BaudNameOnlyTheX4) {
  // No receive times: the baud alone says which unit it is (a unit's baud is fixed).
  const StreamDiagnosis d = fed(test::read_file(test::capture("x4-scan1.bin")));
  const std::string v = verdict_of(d, Model::G6, 128000);
  EXPECT_TRUE(has(v, "2-byte samples (LSN up to 40) at 128000 baud, matching the X4 (model code 6"));
  EXPECT_EQ(v.find("G4 ("), std::string::npos) << v;
  EXPECT_TRUE(has(v, "not a G6"));
}

TEST(StreamDiagnosis, X2BytesNameTheFamiliesAt115200) {
  // One real X2 packet (LSN 40, 90 bytes), repeated at the X2's 3 k samples/s.
  const Bytes bytes = repeated(test::read_hex_capture(test::capture("x2-packet.hex")), 2400);
  const StreamDiagnosis d = fed(bytes, 3000.0 * 90 / 40);
  EXPECT_EQ(d.findings().two_byte_max_lsn, 40);
  const std::string v = verdict_of(d, Model::G6, 115200);
  EXPECT_TRUE(has(v, "2-byte samples (LSN up to 40, about 3.0 k samples/s) at 115200 baud"));
  EXPECT_TRUE(has(v, "X2 (model code 6, 115200 baud, 3 k samples/s)"));
  EXPECT_TRUE(has(v, "S2 (model code 4/12"));
  EXPECT_EQ(v.find("X4 ("), std::string::npos) << v;
}

// ---- 3-byte samples with intensity ----------------------------------------------------------

// tier4/ydlidar_driver (a T-mini Pro driver), ydlidar_signal_parser/src/checksum.rs at commit
// 7fdc35a8f3f6849881ca1fc6566e2b67c4e34256, test_calc_checksum: two T-mini Pro packets.
const Bytes kTminiPro39 = {
    0xAA, 0x55, 0xB0, 0x27, 0xE3, 0x28, 0xF3, 0x39, 0x0E, 0x61, 0x79, 0xB6, 0x05, 0x6F, 0x4E, 0x06, 0x61, 0x06, 0x06,
    0x7A, 0x9A, 0x02, 0x9E, 0x5E, 0x02, 0xA6, 0x0A, 0x02, 0xA7, 0xE6, 0x01, 0xAE, 0xD6, 0x01, 0xBA, 0xD6, 0x01, 0xB8,
    0xD2, 0x01, 0xB2, 0xD6, 0x01, 0xBD, 0xD2, 0x01, 0xDF, 0xDA, 0x01, 0xE1, 0xDA, 0x01, 0xDF, 0xDA, 0x01, 0xDC, 0xDE,
    0x01, 0xDE, 0xDE, 0x01, 0xD8, 0xE2, 0x01, 0xD4, 0xDE, 0x01, 0xBA, 0xDE, 0x01, 0x84, 0xDF, 0x01, 0x2F, 0xAB, 0x01,
    0x17, 0xEE, 0x01, 0x0F, 0x22, 0x02, 0x0C, 0x7E, 0x02, 0x0A, 0x02, 0x00, 0x0C, 0x9E, 0x02, 0x16, 0xA6, 0x02, 0x21,
    0xA2, 0x02, 0x3A, 0x32, 0x03, 0x55, 0x4E, 0x0A, 0x87, 0x46, 0x0A, 0x85, 0x5A, 0x0A, 0x8A, 0x6E, 0x0A, 0x84, 0x9A,
    0x0A, 0x7E, 0xCE, 0x0A, 0x4E, 0x7E, 0x04, 0x51, 0x6E, 0x03, 0x66, 0xA6, 0x02,
};
const Bytes kTminiPro40 = {
    0xAA, 0x55, 0x24, 0x28, 0xF5, 0x4C, 0x85, 0x5E, 0x9D, 0x70, 0xCE, 0xE2, 0x07, 0xBC, 0xFA, 0x07, 0xCC, 0xB6, 0x07,
    0xC8, 0xB6, 0x07, 0xC4, 0xBA, 0x07, 0xCB, 0xCA, 0x07, 0xC8, 0xAE, 0x09, 0xC5, 0x9E, 0x09, 0xC7, 0x9E, 0x09, 0xC2,
    0x9E, 0x09, 0xC1, 0x92, 0x09, 0xC0, 0x8A, 0x09, 0xC1, 0x86, 0x09, 0xBE, 0x86, 0x09, 0xC5, 0x86, 0x09, 0xC3, 0x8A,
    0x09, 0xBC, 0x8A, 0x09, 0xC6, 0x8A, 0x09, 0xC6, 0x8A, 0x09, 0xC2, 0x8E, 0x09, 0xC5, 0x8E, 0x09, 0xC3, 0x92, 0x09,
    0xC4, 0xAA, 0x09, 0xC9, 0xB2, 0x09, 0xC9, 0xBA, 0x09, 0xC5, 0xC2, 0x09, 0xC9, 0xCE, 0x09, 0xBF, 0xCE, 0x09, 0xBE,
    0xCE, 0x09, 0xBA, 0xCE, 0x09, 0xBE, 0xD6, 0x09, 0xBB, 0xD6, 0x09, 0xBF, 0xE2, 0x09, 0xBB, 0xF2, 0x09, 0xC1, 0x0A,
    0x0A, 0xBF, 0x1A, 0x0A, 0xB9, 0x1E, 0x0A, 0xAA, 0x22, 0x0A, 0x9E, 0x2A, 0x0A, 0xCB, 0x7A, 0x15,
};

TEST(StreamDiagnosis, TminiProPacketsVerifyAsThreeByteSamples) {
  ASSERT_EQ(kTminiPro39.size(), 10u + 3 * 39);
  ASSERT_EQ(kTminiPro40.size(), 10u + 3 * 40);
  Bytes pair = kTminiPro39;
  test::append(pair, kTminiPro40);
  const StreamDiagnosis d = fed(repeated(pair, 2600));
  const StreamFindings f = d.findings();
  EXPECT_EQ(f.three_byte_packets, 2 * (f.window_bytes / pair.size()));
  EXPECT_EQ(f.three_byte_max_lsn, 40);
  EXPECT_EQ(f.two_byte_packets, 0u);
  const std::string v = verdict_of(d, Model::G6, 230400);
  EXPECT_TRUE(has(v, "these packets verify as 3-byte samples with intensity (LSN up to 40)"));
  EXPECT_TRUE(has(v, "T-mini Pro (model code 150, 230400 baud"));
  EXPECT_TRUE(has(v, "which the G6 does not use"));
  EXPECT_TRUE(has(v, "ydscope decodes G1, G6, TG15, TG30, TG50 only"));
}

// A 3-byte-sample packet built from the layout alone: per sample an intensity byte, then the u16
// distance word; the checksum XORs the intensity (high byte 0) and the word.
Bytes intensity_packet(std::uint8_t ct, double fsa_deg, double lsa_deg, std::uint8_t lsn, std::uint16_t seed) {
  const std::uint16_t fsa = encode_raw_angle(fsa_deg), lsa = encode_raw_angle(lsa_deg);
  Bytes out(10 + 3 * std::size_t{lsn});
  out[0] = 0xAA, out[1] = 0x55, out[2] = ct, out[3] = lsn;
  write_u16_le(&out[4], fsa);
  write_u16_le(&out[6], lsa);
  std::uint16_t cs = static_cast<std::uint16_t>(0x55AA ^ (ct | (lsn << 8)) ^ fsa ^ lsa);
  for (std::size_t i = 0; i < lsn; ++i) {
    const auto intensity = static_cast<std::uint8_t>(seed * 7 + i);
    const auto distance = static_cast<std::uint16_t>((1500 + 3 * seed + i) << 2);  // triangle: mm << 2
    out[10 + 3 * i] = intensity;
    write_u16_le(&out[11 + 3 * i], distance);
    cs = static_cast<std::uint16_t>(cs ^ intensity ^ distance);
  }
  write_u16_le(&out[8], cs);
  return out;
}

TEST(StreamDiagnosis, BuiltIntensityStreamNamesTheFamilyAtTheLineBaud) {
  Bytes bytes;
  for (std::uint16_t lap = 0; bytes.size() < 4000; ++lap) {
    test::append(bytes, intensity_packet(kCtLapStart, 0, 0, 1, lap));
    for (int i = 0; i < 9; ++i) test::append(bytes, intensity_packet(0, i * 40.0 + 0.5, i * 40.0 + 39.5, 30, lap));
  }
  const StreamDiagnosis d = fed(bytes);
  EXPECT_EQ(d.findings().two_byte_packets, 0u);
  EXPECT_TRUE(has(verdict_of(d, Model::G1, 230400), "3-byte samples with intensity (LSN up to 30)"));
  // At 512000 baud the one 3-byte family there is the G4B.
  const std::string at_512k = verdict_of(d, Model::TG30, 512000);
  EXPECT_TRUE(has(at_512k, "the layout of the G4B (model code 17, 512000 baud, 10 k samples/s, 10-bit intensity)"));
  EXPECT_EQ(at_512k.find("T-mini"), std::string::npos) << at_512k;
}

// ---- a wrong baud: the G6's UART bits read at another rate ------------------------------------

TEST(StreamDiagnosis, ResamplerIsExactAtTheSameBaud) {
  const Bytes g6 = test::synthetic_stream(1, 4, 10);
  EXPECT_EQ(test::resample_uart(g6, 512000, 512000), g6);
}

struct WrongBaud {
  std::uint32_t sent, read;
  const char* advice;
};

class StreamDiagnosisWrongBaud : public ::testing::TestWithParam<WrongBaud> {};

TEST_P(StreamDiagnosisWrongBaud, SaysTryAnotherBaud) {
  const WrongBaud p = GetParam();
  const Bytes line = test::resample_uart(test::synthetic_stream(12, 20, 40), p.sent, p.read);
  ASSERT_GE(line.size(), StreamDiagnosis::kMinBytes);
  const StreamDiagnosis d = fed(line);
  EXPECT_LT(d.findings().two_byte_packets, 3u);
  const std::string v = verdict_of(d, Model::G6, p.read);
  EXPECT_TRUE(has(v, "bytes arrive but no valid packets at " + std::to_string(p.read) +
                         " baud: the line looks like another baud (no AA 55 packet headers"));
  EXPECT_TRUE(has(v, p.advice));
}

INSTANTIATE_TEST_SUITE_P(
    G6Stream, StreamDiagnosisWrongBaud,
    ::testing::Values(WrongBaud{512000, 230400, "try --baud auto, or --baud 512000, 128000 or 115200"},
                      WrongBaud{512000, 115200, "try --baud auto, or --baud 512000, 230400 or 128000"},
                      WrongBaud{512000, 128000, "try --baud auto, or --baud 512000, 230400 or 115200"},
                      WrongBaud{230400, 512000, "try --baud auto, or --baud 230400, 128000 or 115200"}),
    [](const ::testing::TestParamInfo<WrongBaud>& param_info) {
      return "sent" + std::to_string(param_info.param.sent) + "read" + std::to_string(param_info.param.read);
    });

TEST(StreamDiagnosis, SilentLineOfZerosSaysSo) {
  const StreamDiagnosis d = fed(Bytes(3000, 0x00));
  EXPECT_TRUE(has(verdict_of(d, Model::G1, 230400), "nearly every byte 0x00); try --baud auto, or --baud 512000"));
}

// ---- damaged packets, replies only ---------------------------------------------------------

TEST(StreamDiagnosis, HeadersThatNeverVerifySayDamaged) {
  Bytes bytes = test::synthetic_stream(6, 20, 40);
  for (std::size_t at = 0; at + 10 < bytes.size(); at += packet_size(bytes[at + 3]))
    bytes[at + 10] ^= 0x10;  // a flipped bit in every packet's first sample
  const StreamDiagnosis d = fed(bytes);
  ASSERT_LT(d.findings().two_byte_packets, 3u);
  const std::string v = verdict_of(d, Model::G6, 512000);
  EXPECT_TRUE(has(v, "AA 55 packet headers in the last 8192 bytes, but none verifies"));
  EXPECT_TRUE(has(v, "damaged on the way"));
}

TEST(StreamDiagnosis, OnlyRepliesSayTheLidarDoesNotStream) {
  Bytes reply = {0xA5, 0x5A, 0x14, 0x00, 0x00, 0x00, 0x04};  // device info: 20 bytes follow
  reply.resize(reply.size() + 20, 0x33);
  const StreamDiagnosis d = fed(repeated(reply, 3000));
  EXPECT_TRUE(has(verdict_of(d, Model::TG15, 512000), "only command replies (A5 5A) come, no scan packets"));
}

// ---- healthy streams and bounds ----------------------------------------------------------------

TEST(StreamDiagnosis, HealthyStreamsHaveNoVerdict) {
  const Bytes g6 = test::synthetic_stream(6, 20, 40);
  ASSERT_GE(g6.size(), StreamDiagnosis::kMinBytes);
  EXPECT_FALSE(fed(g6).verdict(profile_for(Model::G6), 512000));
  // Paced as a real G6 at 18 k samples/s (about 2.25 bytes a sample here).
  const StreamDiagnosis paced = fed(g6, 18000 * 2.25);
  EXPECT_FALSE(paced.verdict(profile_for(Model::G6), 512000)) << *paced.verdict(profile_for(Model::G6), 512000);
  EXPECT_FALSE(fed(g6, 20000 * 2.25).verdict(profile_for(Model::TG30), 512000));
  EXPECT_FALSE(fed(g6, 9000 * 2.25).verdict(profile_for(Model::G1), 230400));
  // A TCP link or a replay has no baud: the layout alone is enough.
  EXPECT_FALSE(fed(g6).verdict(profile_for(Model::TG50), 0));
}

TEST(StreamDiagnosis, NoVerdictBeforeEnoughBytes) {
  const StreamDiagnosis d = fed(Bytes(StreamDiagnosis::kMinBytes - 1, 0x5C));
  EXPECT_FALSE(d.verdict(profile_for(Model::G6), 512000));
}

TEST(StreamDiagnosis, MemoryIsBoundedAndChunkingDoesNotMatter) {
  std::mt19937 rng(7);
  Bytes noise(1 << 20);
  for (auto& b : noise) b = static_cast<std::uint8_t>(rng());
  StreamDiagnosis d = fed(noise, 0, 4099);
  EXPECT_EQ(d.bytes_seen(), noise.size());
  EXPECT_EQ(d.window_size(), StreamDiagnosis::kWindowBytes);
  EXPECT_TRUE(has(verdict_of(d, Model::G6, 512000), "the line looks like another baud"));
  d.reset();
  EXPECT_EQ(d.window_size(), 0u);
  EXPECT_FALSE(d.verdict(profile_for(Model::G6), 512000));

  const Bytes x4 = test::read_file(test::capture("x4-scan1.bin"));
  const StreamFindings whole = fed(x4, 0, x4.size()).findings();
  const StreamFindings bytewise = fed(x4, 0, 1).findings();
  EXPECT_EQ(whole.two_byte_packets, bytewise.two_byte_packets);
  EXPECT_EQ(whole.headers, bytewise.headers);
}

}  // namespace
}  // namespace ydscope
