// Every command of each manual, against the virtual lidar, byte by byte. The expected bytes are
// written out from the manuals (A5 5A, u32 length | mode << 30, type code, payload), not built
// with the encoders under test.
#include <gtest/gtest.h>

#include <algorithm>
#include <map>

#include "core/protocol/model_profile.h"
#include "core/sim/virtual_lidar.h"
#include "sim/sim_test_support.h"

namespace ydscope {
namespace {

using test::bytes;
using test::exchange;
using test::kMs;
using test::run_for;

using test::kNoReply;
using test::kScanHeader;
using test::scan_hz_reply;
using test::single_reply;

std::vector<std::uint8_t> one_byte(std::uint8_t value) { return single_reply(0x01, 0x04, {value}); }

bool is_g1(Model m) { return m == Model::G1; }
using test::is_tg;

class Conformance : public ::testing::TestWithParam<Model> {
 protected:
  VirtualLidarConfig config() const {
    VirtualLidarConfig c;
    c.model = GetParam();
    c.seed = 7;
    return c;
  }
  const ModelProfile& profile() const { return profile_for(GetParam()); }
  std::uint8_t health_code() const { return is_g1(GetParam()) ? 0x92 : 0x91; }
  std::uint8_t other_health_code() const { return is_g1(GetParam()) ? 0x91 : 0x92; }
  std::uint8_t restart_code() const { return is_g1(GetParam()) ? 0x40 : 0x80; }
  std::uint32_t default_centihz() const { return is_g1(GetParam()) ? 900u : GetParam() == Model::G6 ? 800u : 1000u; }
  std::int64_t now = 0;
};

TEST_P(Conformance, IdleAtPowerOnSendsNothing) {
  VirtualLidar lidar(config());
  std::vector<std::uint8_t> out;
  lidar.produce(5'000 * kMs, out);
  EXPECT_TRUE(out.empty());
  EXPECT_EQ(lidar.mode(), DeviceMode::Idle);
}

TEST_P(Conformance, DeviceInfoCarriesModelFirmwareHardwareSerial) {
  VirtualLidarConfig c = config();
  c.firmware_major = 2;
  c.firmware_minor = 5;
  c.hardware = 3;
  VirtualLidar lidar(c);
  const auto reply = exchange(lidar, {0xA5, 0x90}, now);
  ASSERT_EQ(reply.size(), 7u + 20u);
  const std::vector<std::uint8_t> head(reply.begin(), reply.begin() + 11);
  EXPECT_EQ(head, single_reply(0x14, 0x04, {profile().model_code, 2, 5, 3}));
  for (std::size_t i = 11; i < reply.size(); ++i) EXPECT_LT(reply[i], 10) << "serial digit " << i - 11;
  // The model codes seen in the field (docs/conventions.md): G1 19, G6 13, TG15/30/50 100/101/102.
  const std::map<Model, int> codes{
      {Model::G1, 19}, {Model::G6, 13}, {Model::TG15, 100}, {Model::TG30, 101}, {Model::TG50, 102}};
  EXPECT_EQ(reply[7], codes.at(GetParam()));
}

// The app starts several virtual lidars from one seed: each is a unit of its own by serial
// (core/frame/unit_identity.h), and nothing else it sends differs.
TEST_P(Conformance, UnitsOfOneSeedAnswerWithSerialsOfTheirOwnAndTheSameScan) {
  VirtualLidarConfig second = config();
  second.unit = 1;
  VirtualLidar first_lidar(config()), second_lidar(second);
  std::int64_t first_now = 0, second_now = 0;
  const auto first_info = exchange(first_lidar, {0xA5, 0x90}, first_now);
  const auto second_info = exchange(second_lidar, {0xA5, 0x90}, second_now);
  ASSERT_EQ(first_info.size(), 27u);
  ASSERT_EQ(second_info.size(), 27u);
  EXPECT_TRUE(std::equal(first_info.begin(), first_info.begin() + 11, second_info.begin()));  // header, model, firmware
  EXPECT_FALSE(std::equal(first_info.begin() + 11, first_info.end(), second_info.begin() + 11));  // the serial
  exchange(first_lidar, {0xA5, 0x60}, first_now);
  exchange(second_lidar, {0xA5, 0x60}, second_now);
  EXPECT_EQ(run_for(first_lidar, first_now, 500 * kMs), run_for(second_lidar, second_now, 500 * kMs));
}

TEST_P(Conformance, HealthAnswersOnTheManualsCommandOnly) {
  VirtualLidar lidar(config());
  EXPECT_EQ(exchange(lidar, {0xA5, health_code()}, now), single_reply(0x03, 0x06, {0x00, 0x00, 0x00}));
  EXPECT_EQ(exchange(lidar, {0xA5, other_health_code()}, now), kNoReply);
  EXPECT_EQ(lidar.counters().unsupported, 1u);
}

TEST_P(Conformance, RaisedHealthBitsShowInTheHealthReply) {
  VirtualLidarConfig c = config();
  c.faults.health_bits = 0x05;
  VirtualLidar lidar(c);
  const auto expected = is_g1(GetParam()) ? single_reply(0x03, 0x06, {0x05, 0x00, 0x00})   // status bits
                                          : single_reply(0x03, 0x06, {0x02, 0x05, 0x00});  // error + code
  EXPECT_EQ(exchange(lidar, {0xA5, health_code()}, now), expected);
}

TEST_P(Conformance, HealthQuirkAnswersOnlyTheOtherCommand) {
  VirtualLidarConfig c = config();
  c.health_quirk = true;
  VirtualLidar lidar(c);
  EXPECT_EQ(exchange(lidar, {0xA5, health_code()}, now), kNoReply);
  EXPECT_EQ(exchange(lidar, {0xA5, other_health_code()}, now), single_reply(0x03, 0x06, {0x00, 0x00, 0x00}));
}

TEST_P(Conformance, ScanFrequencySteppingAndReadBack) {
  VirtualLidar lidar(config());
  const std::uint32_t f = default_centihz();
  EXPECT_EQ(exchange(lidar, {0xA5, 0x0D}, now), scan_hz_reply(f));
  EXPECT_EQ(exchange(lidar, {0xA5, 0x09}, now), scan_hz_reply(f + 10));
  EXPECT_EQ(exchange(lidar, {0xA5, 0x0B}, now), scan_hz_reply(f + 110));
  EXPECT_EQ(exchange(lidar, {0xA5, 0x0A}, now), scan_hz_reply(f + 100));
  EXPECT_EQ(exchange(lidar, {0xA5, 0x0C}, now), scan_hz_reply(f));
  EXPECT_EQ(exchange(lidar, {0xA5, 0x0D}, now), scan_hz_reply(f));
  EXPECT_EQ(lidar.scan_centihz(), f);
}

TEST_P(Conformance, ScanFrequencyIsClampedToTheModelsLimits) {
  VirtualLidar lidar(config());
  const auto max = static_cast<std::uint32_t>(profile().max_scan_hz * 100 + 0.5);
  const auto min = static_cast<std::uint32_t>(profile().min_scan_hz * 100 + 0.5);
  for (int i = 0; i < 20; ++i) exchange(lidar, {0xA5, 0x0B}, now);
  EXPECT_EQ(exchange(lidar, {0xA5, 0x09}, now), scan_hz_reply(max));
  for (int i = 0; i < 20; ++i) exchange(lidar, {0xA5, 0x0C}, now);
  EXPECT_EQ(exchange(lidar, {0xA5, 0x0A}, now), scan_hz_reply(min));
  EXPECT_EQ(exchange(lidar, {0xA5, 0x09}, now), scan_hz_reply(min + 10));
}

TEST_P(Conformance, RangingReadBackAndCycling) {
  VirtualLidar lidar(config());
  // Defaults: G1 9 kHz is index 3 of 4/5/8/9/10/16/18; G6/TG 9 kHz is index 2 of 4/8/9.
  const std::uint8_t start = is_g1(GetParam()) ? 3 : 2;
  EXPECT_EQ(exchange(lidar, {0xA5, 0xD1}, now), one_byte(start));
  if (is_g1(GetParam())) {
    EXPECT_EQ(exchange(lidar, {0xA5, 0xD0}, now), kNoReply);  // G1 can only read it
    return;
  }
  EXPECT_EQ(exchange(lidar, {0xA5, 0xD0}, now), one_byte(0));  // 4 kHz
  EXPECT_EQ(lidar.ranging_khz(), 4);
  EXPECT_EQ(exchange(lidar, {0xA5, 0xD0}, now), one_byte(1));  // 8 kHz
  EXPECT_EQ(exchange(lidar, {0xA5, 0xD1}, now), one_byte(1));
  EXPECT_EQ(exchange(lidar, {0xA5, 0xD0}, now), one_byte(2));  // back to 9 kHz
  EXPECT_EQ(lidar.ranging_khz(), 9);
}

TEST_P(Conformance, PowerDownProtectionToggles) {
  VirtualLidar lidar(config());
  EXPECT_FALSE(lidar.power_down_protection());
  EXPECT_EQ(exchange(lidar, {0xA5, 0xD9}, now), one_byte(0x00));  // 00: now enabled
  EXPECT_TRUE(lidar.power_down_protection());
  EXPECT_EQ(exchange(lidar, {0xA5, 0xD9}, now), one_byte(0x01));  // 01: now disabled
  EXPECT_FALSE(lidar.power_down_protection());
}

TEST_P(Conformance, LowPowerMotorDirectionConstantFrequency) {
  VirtualLidar lidar(config());
  if (is_g1(GetParam())) {
    for (const int code : {0x01, 0x02, 0x05, 0x06, 0x07, 0x08, 0x0E, 0x0F, 0x80})
      EXPECT_EQ(exchange(lidar, {0xA5, static_cast<std::uint8_t>(code)}, now), kNoReply) << "A5 " << code;
    EXPECT_EQ(lidar.counters().unsupported, 9u);
    return;
  }
  EXPECT_EQ(exchange(lidar, {0xA5, 0x02}, now), one_byte(0x00));
  EXPECT_FALSE(lidar.low_power());
  if (is_tg(GetParam())) {
    EXPECT_EQ(exchange(lidar, {0xA5, 0x05}, now), one_byte(0x00));  // TG low-power query
  }
  EXPECT_EQ(exchange(lidar, {0xA5, 0x01}, now), one_byte(0x01));
  if (is_tg(GetParam())) {
    EXPECT_EQ(exchange(lidar, {0xA5, 0x05}, now), one_byte(0x01));
  } else {
    EXPECT_EQ(exchange(lidar, {0xA5, 0x05}, now), kNoReply);  // G6 does not list A5 05
  }

  EXPECT_EQ(exchange(lidar, {0xA5, 0x08}, now), one_byte(0x00));  // clockwise by default
  EXPECT_EQ(exchange(lidar, {0xA5, 0x07}, now), one_byte(0x01));
  EXPECT_EQ(exchange(lidar, {0xA5, 0x08}, now), one_byte(0x01));
  EXPECT_EQ(exchange(lidar, {0xA5, 0x06}, now), one_byte(0x00));

  EXPECT_EQ(exchange(lidar, {0xA5, 0x0F}, now), one_byte(0x00));
  EXPECT_FALSE(lidar.constant_frequency());
  EXPECT_EQ(exchange(lidar, {0xA5, 0x0E}, now), one_byte(0x01));
  EXPECT_TRUE(lidar.constant_frequency());
}

TEST_P(Conformance, RestartAnswersNothingAndRestoresPowerOnState) {
  VirtualLidar lidar(config());
  exchange(lidar, {0xA5, 0x0B}, now);
  exchange(lidar, {0xA5, 0xD9}, now);
  EXPECT_EQ(exchange(lidar, {0xA5, is_g1(GetParam()) ? std::uint8_t{0x80} : std::uint8_t{0x40}}, now), kNoReply);
  EXPECT_EQ(lidar.counters().restarts, 0u);  // the other model's restart code is not listed
  EXPECT_EQ(exchange(lidar, {0xA5, restart_code()}, now), kNoReply);
  EXPECT_EQ(lidar.counters().restarts, 1u);
  EXPECT_FALSE(lidar.power_down_protection());
  EXPECT_EQ(exchange(lidar, {0xA5, 0x0D}, now), scan_hz_reply(default_centihz()));
}

TEST_P(Conformance, UnknownCodesAndStrayBytesGetNoReply) {
  VirtualLidar lidar(config());
  EXPECT_EQ(exchange(lidar, {0x00, 0x12, 0xA5, 0x33, 0xA5, 0xA5, 0x90}, now).size(), 27u);  // only A5 90 answers
  EXPECT_EQ(lidar.counters().unsupported, 1u);                                              // A5 33
  EXPECT_EQ(lidar.counters().stray_bytes, 3u);  // 00, 12, and the A5 without a code
}

TEST_P(Conformance, ScanStartsWithTheContinuousHeaderThenPackets) {
  VirtualLidar lidar(config());
  const auto out = exchange(lidar, {0xA5, 0x60}, now, 200 * kMs);
  ASSERT_GT(out.size(), 100u);
  EXPECT_EQ(std::vector<std::uint8_t>(out.begin(), out.begin() + 7), kScanHeader);
  // G1's LastCRC byte and a real TG's byte before the zero packet (0 before the first lap).
  const bool byte_before_zero = lidar.conventions().byte_before_zero != ByteBeforeZero::None;
  const std::size_t first = byte_before_zero ? 8 : 7;
  if (byte_before_zero) {
    EXPECT_EQ(out[7], 0x00);
  }
  EXPECT_EQ(out[first], 0xAA);
  EXPECT_EQ(out[first + 1], 0x55);
  EXPECT_EQ(out[first + 2] & 1, 1);  // zero packet
  EXPECT_EQ(out[first + 3], 1);      // LSN 1
  EXPECT_EQ(lidar.mode(), DeviceMode::Scanning);
}

TEST_P(Conformance, CommandsDuringAScanAreIgnoredAndCounted) {
  VirtualLidar lidar(config());
  exchange(lidar, {0xA5, 0x60}, now, 100 * kMs);
  const auto replies = lidar.counters().replies;
  exchange(lidar, {0xA5, 0x90, 0xA5, 0x0B, 0xA5, 0x60}, now, 100 * kMs);
  EXPECT_EQ(lidar.counters().ignored_during_scan, 3u);  // A5 60 too: protection is off
  EXPECT_EQ(lidar.counters().replies, replies);
  EXPECT_EQ(lidar.scan_centihz(), default_centihz());
  EXPECT_EQ(lidar.mode(), DeviceMode::Scanning);
}

TEST_P(Conformance, StopEndsTheStreamWithoutAReply) {
  VirtualLidar lidar(config());
  exchange(lidar, {0xA5, 0x60}, now, 300 * kMs);
  const auto tail = exchange(lidar, {0xA5, 0x65}, now, 10 * kMs);
  EXPECT_LE(tail.size(), 1u + 10u + 2u * 40u);  // at most the rest of the packet on the line
  EXPECT_EQ(lidar.mode(), DeviceMode::Idle);
  std::vector<std::uint8_t> later;
  lidar.produce(now + 1'000 * kMs, later);
  EXPECT_TRUE(later.empty());
}

TEST_P(Conformance, PowerDownProtectionStopsAScanWithoutKeepAlive) {
  VirtualLidar lidar(config());
  exchange(lidar, {0xA5, 0xD9}, now);
  const std::int64_t start = now;
  exchange(lidar, {0xA5, 0x60}, now, 2'900 * kMs);
  EXPECT_EQ(lidar.mode(), DeviceMode::Scanning);
  std::vector<std::uint8_t> out;
  lidar.produce(start + 3'000 * kMs + 1, out);
  EXPECT_EQ(lidar.mode(), DeviceMode::Idle);
  EXPECT_EQ(lidar.counters().power_down_stops, 1u);
  out.clear();
  lidar.produce(start + 3'010 * kMs, out);
  lidar.produce(start + 5'000 * kMs, out);
  EXPECT_LE(out.size(), 1u + 10u + 2u * 40u);  // only what was on the line at the stop
}

TEST_P(Conformance, PowerDownKeepAliveKeepsTheScanGoingSilently) {
  VirtualLidar lidar(config());
  exchange(lidar, {0xA5, 0xD9}, now);
  exchange(lidar, {0xA5, 0x60}, now, 1'000 * kMs);
  const auto replies = lidar.counters().replies;
  for (int i = 0; i < 8; ++i) exchange(lidar, {0xA5, 0x60}, now, 1'000 * kMs);
  EXPECT_EQ(lidar.mode(), DeviceMode::Scanning);
  EXPECT_EQ(lidar.counters().keepalives, 8u);
  EXPECT_EQ(lidar.counters().replies, replies);  // no second reply header
  EXPECT_EQ(lidar.counters().ignored_during_scan, 0u);
  std::vector<std::uint8_t> out;
  lidar.produce(now + 2'100 * kMs, out);  // the last keep-alive was 1 s ago; 3 s after it: stopped
  EXPECT_EQ(lidar.mode(), DeviceMode::Idle);
  // A fresh A5 60 from the stopped state gets the full header again.
  const auto again = exchange(lidar, {0xA5, 0x60}, now += 3'000 * kMs, 50 * kMs);
  ASSERT_GE(again.size(), 7u);
  EXPECT_EQ(std::vector<std::uint8_t>(again.begin(), again.begin() + 7), kScanHeader);
}

TEST_P(Conformance, RestartDuringAScanIsIgnored) {
  VirtualLidar lidar(config());
  exchange(lidar, {0xA5, 0x60}, now);
  exchange(lidar, {0xA5, restart_code()}, now);
  EXPECT_EQ(lidar.mode(), DeviceMode::Scanning);
  EXPECT_EQ(lidar.counters().restarts, 0u);
}

INSTANTIATE_TEST_SUITE_P(AllModels, Conformance,
                         ::testing::Values(Model::G1, Model::G6, Model::TG15, Model::TG30, Model::TG50),
                         [](const ::testing::TestParamInfo<Model>& param) {
                           return std::string(profile_for(param.param).name);
                         });

}  // namespace
}  // namespace ydscope
