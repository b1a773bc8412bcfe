#include "core/protocol/reply.h"

#include <algorithm>

#include "core/protocol/byte_access.h"

namespace ydscope {

namespace {

constexpr std::uint32_t kModeSingleBits = 0;
constexpr std::uint32_t kModeContinuousBits = 1;

std::optional<bool> parse_flag_byte(std::span<const std::uint8_t> payload, std::uint8_t true_value,
                                    std::uint8_t false_value) {
  const auto value = parse_one_byte(payload);
  if (!value) return std::nullopt;
  if (*value == true_value) return true;
  if (*value == false_value) return false;
  return std::nullopt;
}

}  // namespace

std::array<std::uint8_t, kReplyHeaderSize> encode_reply_header(const ReplyHeader& header) {
  std::array<std::uint8_t, kReplyHeaderSize> out{kReplyStart0, kReplyStart1};
  const std::uint32_t mode_bits = header.mode == ReplyMode::Continuous ? kModeContinuousBits : kModeSingleBits;
  write_u32_le(out.data() + 2, (header.length & kReplyLengthMask) | (mode_bits << 30));
  out[6] = header.type_code;
  return out;
}

std::optional<ReplyHeader> parse_reply_header(std::span<const std::uint8_t> bytes) {
  if (bytes.size() < kReplyHeaderSize || bytes[0] != kReplyStart0 || bytes[1] != kReplyStart1) return std::nullopt;
  const std::uint32_t field = read_u32_le(bytes.data() + 2);
  const std::uint32_t mode_bits = field >> 30;
  if (mode_bits != kModeSingleBits && mode_bits != kModeContinuousBits) return std::nullopt;
  ReplyHeader header;
  header.length = field & kReplyLengthMask;
  header.mode = mode_bits == kModeContinuousBits ? ReplyMode::Continuous : ReplyMode::Single;
  header.type_code = bytes[6];
  return header;
}

ReplyHeader reply_header_for(Command command) {
  const ReplySpec spec = reply_spec(command);
  ReplyHeader header;
  header.mode = spec.mode;
  header.type_code = spec.type_code;
  header.length = spec.mode == ReplyMode::Continuous ? kScanReplyLengthField : spec.payload_length;
  return header;
}

bool reply_matches(const ReplyHeader& header, Command command) {
  const ReplySpec spec = reply_spec(command);
  if (spec.mode == ReplyMode::None || header.mode != spec.mode || header.type_code != spec.type_code) return false;
  return spec.mode == ReplyMode::Continuous || header.length == spec.payload_length;
}

std::vector<std::uint8_t> encode_reply(Command command, std::span<const std::uint8_t> payload) {
  const auto header = encode_reply_header(reply_header_for(command));
  std::vector<std::uint8_t> out(header.size() + payload.size());
  std::copy(header.begin(), header.end(), out.begin());
  std::copy(payload.begin(), payload.end(), out.begin() + static_cast<std::ptrdiff_t>(header.size()));
  return out;
}

std::array<std::uint8_t, kDeviceInfoSize> encode_device_info(const DeviceInfo& info) {
  std::array<std::uint8_t, kDeviceInfoSize> out{};
  out[0] = info.model_code;
  out[1] = info.firmware_major;  // the manuals: low byte major, high byte minor
  out[2] = info.firmware_minor;
  out[3] = info.hardware;
  std::copy(info.serial.begin(), info.serial.end(), out.begin() + 4);
  return out;
}

std::optional<DeviceInfo> parse_device_info(std::span<const std::uint8_t> payload) {
  if (payload.size() != kDeviceInfoSize) return std::nullopt;
  DeviceInfo info;
  info.model_code = payload[0];
  info.firmware_major = payload[1];
  info.firmware_minor = payload[2];
  info.hardware = payload[3];
  std::copy(payload.begin() + 4, payload.end(), info.serial.begin());
  return info;
}

std::string serial_string(const DeviceInfo& info) {
  static constexpr char kHex[] = "0123456789ABCDEF";
  std::string out;
  for (const std::uint8_t byte : info.serial) {
    if (byte >= 16) out.push_back(kHex[byte >> 4]);
    out.push_back(kHex[byte & 0xF]);
  }
  return out;
}

std::array<std::uint8_t, kHealthSize> encode_health(const HealthReply& health) {
  std::array<std::uint8_t, kHealthSize> out{health.status};
  write_u16_le(out.data() + 1, health.error_code);
  return out;
}

std::optional<HealthReply> parse_health(std::span<const std::uint8_t> payload) {
  if (payload.size() != kHealthSize) return std::nullopt;
  return HealthReply{payload[0], read_u16_le(payload.data() + 1)};
}

std::string_view g1_health_bit_name(unsigned bit) {
  switch (bit) {
    case 0: return "sensor";
    case 1: return "encoder";
    case 2: return "power supply";
    case 3: return "laser feedback (PD)";
    case 4: return "laser drive (LD)";
    case 5: return "data";
    default: return "reserved";
  }
}

std::optional<DeviceStatus> device_status(std::uint8_t status) {
  if (status > static_cast<std::uint8_t>(DeviceStatus::Error)) return std::nullopt;
  return static_cast<DeviceStatus>(status);
}

std::string_view device_status_name(DeviceStatus status) {
  switch (status) {
    case DeviceStatus::Normal: return "normal";
    case DeviceStatus::Warning: return "warning";
    case DeviceStatus::Error: return "error";
  }
  return "unknown";
}

std::array<std::uint8_t, kScanFrequencySize> encode_scan_frequency(ScanFrequency frequency) {
  std::array<std::uint8_t, kScanFrequencySize> out{};
  write_u32_le(out.data(), frequency.centihertz);
  return out;
}

std::optional<ScanFrequency> parse_scan_frequency(std::span<const std::uint8_t> payload) {
  if (payload.size() != kScanFrequencySize) return std::nullopt;
  return ScanFrequency{read_u32_le(payload.data())};
}

std::array<std::uint8_t, 1> encode_one_byte(std::uint8_t value) { return {value}; }

std::optional<std::uint8_t> parse_one_byte(std::span<const std::uint8_t> payload) {
  if (payload.size() != kOneByteAnswerSize) return std::nullopt;
  return payload[0];
}

std::optional<std::uint16_t> parse_ranging_khz(const ModelProfile& profile, std::span<const std::uint8_t> payload) {
  const auto index = parse_one_byte(payload);
  if (!index || *index >= profile.ranging_khz.size()) return std::nullopt;
  return profile.ranging_khz[*index];
}

std::optional<bool> parse_power_down_protection(std::span<const std::uint8_t> payload) {
  return parse_flag_byte(payload, 0x00, 0x01);  // inverted on purpose: the manuals say 00 = on
}

std::array<std::uint8_t, 1> encode_power_down_protection(bool enabled) {
  return {static_cast<std::uint8_t>(enabled ? 0x00 : 0x01)};
}

std::optional<bool> parse_low_power(std::span<const std::uint8_t> payload) {
  return parse_flag_byte(payload, 0x01, 0x00);
}

std::array<std::uint8_t, 1> encode_low_power(bool enabled) {
  return {static_cast<std::uint8_t>(enabled ? 0x01 : 0x00)};
}

std::optional<MotorDirection> parse_motor_direction(std::span<const std::uint8_t> payload) {
  const auto counter_clockwise = parse_flag_byte(payload, 0x01, 0x00);
  if (!counter_clockwise) return std::nullopt;
  return *counter_clockwise ? MotorDirection::CounterClockwise : MotorDirection::Clockwise;
}

std::array<std::uint8_t, 1> encode_motor_direction(MotorDirection direction) {
  return {static_cast<std::uint8_t>(direction)};
}

std::optional<bool> parse_constant_frequency(std::span<const std::uint8_t> payload) {
  return parse_flag_byte(payload, 0x01, 0x00);
}

std::array<std::uint8_t, 1> encode_constant_frequency(bool enabled) {
  return {static_cast<std::uint8_t>(enabled ? 0x01 : 0x00)};
}

std::optional<std::uint8_t> parse_module_status(std::span<const std::uint8_t> payload) {
  return parse_one_byte(payload);
}

}  // namespace ydscope
