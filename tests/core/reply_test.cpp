// Reply headers and payloads of every command the three manuals document.
#include <gtest/gtest.h>

#include "core/protocol/reply.h"

namespace ydscope {
namespace {

using Bytes = std::vector<std::uint8_t>;

Bytes header_bytes(Command command) {
  const auto h = encode_reply_header(reply_header_for(command));
  return Bytes(h.begin(), h.end());
}

TEST(ReplyHeader, ManualHeadersOfEachCommand) {
  // The manuals' figures: device info length 0x14 mode 0 type 04; health 3/0/06; scan frequency
  // 4/0/04; one-byte answers 1/0/04; the scan reply A5 5A 05 00 00 40 81 (mode 1, type 81).
  EXPECT_EQ(header_bytes(Command::DeviceInfo), (Bytes{0xA5, 0x5A, 0x14, 0x00, 0x00, 0x00, 0x04}));
  EXPECT_EQ(header_bytes(Command::HealthStatusBits), (Bytes{0xA5, 0x5A, 0x03, 0x00, 0x00, 0x00, 0x06}));
  EXPECT_EQ(header_bytes(Command::HealthStatusCode), (Bytes{0xA5, 0x5A, 0x03, 0x00, 0x00, 0x00, 0x06}));
  EXPECT_EQ(header_bytes(Command::Scan), (Bytes{0xA5, 0x5A, 0x05, 0x00, 0x00, 0x40, 0x81}));
  for (Command c : {Command::ScanHzUpTenth, Command::ScanHzDownTenth, Command::ScanHzUpOne, Command::ScanHzDownOne,
                    Command::ScanHzGet})
    EXPECT_EQ(header_bytes(c), (Bytes{0xA5, 0x5A, 0x04, 0x00, 0x00, 0x00, 0x04})) << command_name(c);
  for (Command c : {Command::RangingGet, Command::RangingCycle, Command::PowerDownProtection, Command::LowPowerOn,
                    Command::LowPowerOff, Command::MotorClockwise, Command::MotorCounterClockwise,
                    Command::MotorDirection, Command::ConstantHzOn, Command::ConstantHzOff, Command::ModuleStatus})
    EXPECT_EQ(header_bytes(c), (Bytes{0xA5, 0x5A, 0x01, 0x00, 0x00, 0x00, 0x04})) << command_name(c);
}

TEST(ReplyHeader, ParsesLengthModeAndType) {
  const Bytes scan{0xA5, 0x5A, 0x05, 0x00, 0x00, 0x40, 0x81};
  const auto h = parse_reply_header(scan);
  ASSERT_TRUE(h);
  EXPECT_EQ(h->length, 5u);
  EXPECT_EQ(h->mode, ReplyMode::Continuous);
  EXPECT_EQ(h->type_code, 0x81);
  EXPECT_TRUE(reply_matches(*h, Command::Scan));
  EXPECT_FALSE(reply_matches(*h, Command::DeviceInfo));

  // The low 6 bits of byte 6 belong to the length: a 30-bit length.
  const Bytes big{0xA5, 0x5A, 0xFF, 0xFF, 0xFF, 0x3F, 0x04};
  const auto b = parse_reply_header(big);
  ASSERT_TRUE(b);
  EXPECT_EQ(b->length, 0x3FFFFFFFu);
  EXPECT_EQ(b->mode, ReplyMode::Single);
  EXPECT_FALSE(reply_matches(*b, Command::DeviceInfo));  // bounded: only 20 is a device-info reply
}

TEST(ReplyHeader, RejectsWrongStartUndefinedModeAndShortInput) {
  EXPECT_FALSE(parse_reply_header(Bytes{0xA5, 0x5B, 0x14, 0x00, 0x00, 0x00, 0x04}));
  EXPECT_FALSE(parse_reply_header(Bytes{0xA5, 0x5A, 0x14, 0x00, 0x00, 0x80, 0x04}));  // mode 2
  EXPECT_FALSE(parse_reply_header(Bytes{0xA5, 0x5A, 0x14, 0x00, 0x00, 0xC0, 0x04}));  // mode 3
  EXPECT_FALSE(parse_reply_header(Bytes{0xA5, 0x5A, 0x14, 0x00, 0x00, 0x00}));
}

TEST(ReplyHeader, RoundTripsEveryCommandThatAnswers) {
  for (int code = 0; code < 256; ++code) {
    const auto command = command_from_code(static_cast<std::uint8_t>(code));
    if (!command || reply_spec(*command).mode == ReplyMode::None) continue;
    const auto bytes = encode_reply_header(reply_header_for(*command));
    const auto parsed = parse_reply_header(bytes);
    ASSERT_TRUE(parsed) << code;
    EXPECT_EQ(*parsed, reply_header_for(*command));
    EXPECT_TRUE(reply_matches(*parsed, *command)) << code;
  }
}

TEST(ReplyPayload, DeviceInfoLayout) {
  // G1 model code 19; firmware: low byte major, high byte minor.
  Bytes payload{19, 3, 7, 2};
  for (std::uint8_t i = 0; i < 16; ++i) payload.push_back(i);
  const auto info = parse_device_info(payload);
  ASSERT_TRUE(info);
  EXPECT_EQ(info->model_code, 19);
  EXPECT_EQ(info->firmware_major, 3);
  EXPECT_EQ(info->firmware_minor, 7);
  EXPECT_EQ(info->hardware, 2);
  EXPECT_EQ(info->serial[15], 15);
  EXPECT_EQ(serial_string(*info), "0123456789ABCDEF");
  const auto encoded = encode_device_info(*info);
  EXPECT_EQ(Bytes(encoded.begin(), encoded.end()), payload);
  payload.pop_back();
  EXPECT_FALSE(parse_device_info(payload));
}

TEST(ReplyPayload, HealthStatusAndErrorCode) {
  const auto g1 = parse_health(Bytes{kG1HealthEncoder | kG1HealthData, 0x34, 0x12});
  ASSERT_TRUE(g1);
  EXPECT_EQ(g1->status, 0x22);
  EXPECT_EQ(g1->error_code, 0x1234);
  EXPECT_EQ(g1_health_bit_name(1), "encoder");
  const auto g6 = parse_health(Bytes{2, 0, 0});
  ASSERT_TRUE(g6);
  EXPECT_EQ(device_status(g6->status), DeviceStatus::Error);
  EXPECT_FALSE(device_status(3));
  const auto encoded = encode_health({1, 0xBEEF});
  EXPECT_EQ(Bytes(encoded.begin(), encoded.end()), (Bytes{1, 0xEF, 0xBE}));
  EXPECT_FALSE(parse_health(Bytes{0, 0}));
}

TEST(ReplyPayload, ScanFrequencyIsHundredthsOfHertz) {
  // 900 = 0x384 -> 9.00 Hz
  const auto f = parse_scan_frequency(Bytes{0x84, 0x03, 0x00, 0x00});
  ASSERT_TRUE(f);
  EXPECT_EQ(f->centihertz, 900u);
  EXPECT_DOUBLE_EQ(f->hz(), 9.0);
  const auto encoded = encode_scan_frequency({1230});
  EXPECT_EQ(Bytes(encoded.begin(), encoded.end()), (Bytes{0xCE, 0x04, 0x00, 0x00}));
  EXPECT_FALSE(parse_scan_frequency(Bytes{0x84, 0x03, 0x00}));
}

TEST(ReplyPayload, G1RangingTable) {
  const auto& g1 = profile_for(Model::G1);
  const std::uint16_t expected[] = {4, 5, 8, 9, 10, 16, 18};
  for (std::uint8_t i = 0; i < 7; ++i) EXPECT_EQ(parse_ranging_khz(g1, Bytes{i}), expected[i]) << int(i);
  EXPECT_FALSE(parse_ranging_khz(g1, Bytes{7}));
  EXPECT_FALSE(parse_ranging_khz(g1, Bytes{0, 0}));
}

TEST(ReplyPayload, G6AndTgRangingTable) {
  for (Model m : {Model::G6, Model::TG15, Model::TG30, Model::TG50}) {
    const auto& p = profile_for(m);
    EXPECT_EQ(parse_ranging_khz(p, Bytes{0}), 4);
    EXPECT_EQ(parse_ranging_khz(p, Bytes{1}), 8);
    EXPECT_EQ(parse_ranging_khz(p, Bytes{2}), 9);
    EXPECT_FALSE(parse_ranging_khz(p, Bytes{3}));
  }
}

TEST(ReplyPayload, OneByteAnswersFollowTheManuals) {
  // Power-down protection: 00 means enabled, 01 disabled (the manuals' inverted convention).
  EXPECT_EQ(parse_power_down_protection(Bytes{0x00}), true);
  EXPECT_EQ(parse_power_down_protection(Bytes{0x01}), false);
  EXPECT_FALSE(parse_power_down_protection(Bytes{0x02}));
  EXPECT_EQ(encode_power_down_protection(true)[0], 0x00);
  // Low power: A5 01 answers 01, A5 02 answers 00.
  EXPECT_EQ(parse_low_power(Bytes{0x01}), true);
  EXPECT_EQ(parse_low_power(Bytes{0x00}), false);
  EXPECT_EQ(encode_low_power(false)[0], 0x00);
  // Motor direction: 00 clockwise, 01 counter-clockwise.
  EXPECT_EQ(parse_motor_direction(Bytes{0x00}), MotorDirection::Clockwise);
  EXPECT_EQ(parse_motor_direction(Bytes{0x01}), MotorDirection::CounterClockwise);
  EXPECT_FALSE(parse_motor_direction(Bytes{0x05}));
  EXPECT_EQ(encode_motor_direction(MotorDirection::CounterClockwise)[0], 0x01);
  // Constant frequency: A5 0E answers 01, A5 0F answers 00.
  EXPECT_EQ(parse_constant_frequency(Bytes{0x01}), true);
  EXPECT_EQ(parse_constant_frequency(Bytes{0x00}), false);
  EXPECT_EQ(encode_constant_frequency(true)[0], 0x01);
  // TG module status is reported raw.
  EXPECT_EQ(parse_module_status(Bytes{0x5C}), 0x5C);
  EXPECT_FALSE(parse_module_status(Bytes{}));
}

TEST(ReplyPayload, EncodeReplyIsHeaderThenPayload) {
  const auto info = encode_device_info({13, 1, 2, 3, {}});
  const Bytes reply = encode_reply(Command::DeviceInfo, info);
  ASSERT_EQ(reply.size(), kReplyHeaderSize + kDeviceInfoSize);
  EXPECT_EQ(reply[2], 0x14);
  EXPECT_EQ(reply[7], 13);
}

}  // namespace
}  // namespace ydscope
