#pragma once
// Replies to A5 xx commands: the 7-byte `A5 5A` header and every payload of the three manuals.
//
// Header: A5 5A, then a u32 little-endian whose low 30 bits are the payload length and top 2 bits
// the mode (0 single, 1 continuous, 2/3 undefined), then the type code.
// Every parser takes the payload as a span and checks its exact size: nothing is sized or
// allocated from a length the device sent. Encoders exist for tests and the virtual lidar.
#include <array>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "core/protocol/commands.h"
#include "core/protocol/model_profile.h"

namespace ydscope {

inline constexpr std::size_t kReplyHeaderSize = 7;
inline constexpr std::uint8_t kReplyStart0 = 0xA5;
inline constexpr std::uint8_t kReplyStart1 = 0x5A;
inline constexpr std::uint32_t kReplyLengthMask = 0x3FFFFFFF;
// The largest payload any command of the manuals answers (device info).
inline constexpr std::size_t kMaxReplyPayload = 20;
// Real devices put 5 in the (ignored) length field of the continuous scan reply: A5 5A 05 00 00 40 81.
inline constexpr std::uint32_t kScanReplyLengthField = 5;

struct ReplyHeader {
  std::uint32_t length = 0;            // 30 bits; meaningless for Continuous
  ReplyMode mode = ReplyMode::Single;  // Single or Continuous; never None in a parsed header
  std::uint8_t type_code = 0;

  friend bool operator==(const ReplyHeader&, const ReplyHeader&) = default;
};

// mode must be Single or Continuous; length is masked to 30 bits.
std::array<std::uint8_t, kReplyHeaderSize> encode_reply_header(const ReplyHeader& header);
// Needs at least kReplyHeaderSize bytes. Empty when the bytes do not start with A5 5A, or when the
// mode bits are one of the manuals' undefined values (2, 3).
std::optional<ReplyHeader> parse_reply_header(std::span<const std::uint8_t> bytes);

// The header a device sends in answer to `command` (mode None: no header; returns mode None).
ReplyHeader reply_header_for(Command command);
// True when `header` is what `command` answers: same mode and type code, and for a single reply
// exactly the payload length of reply_spec(command).
bool reply_matches(const ReplyHeader& header, Command command);

// Header + payload as a device sends them (tests, virtual lidar).
std::vector<std::uint8_t> encode_reply(Command command, std::span<const std::uint8_t> payload);

// ---- payloads --------------------------------------------------------------------------------

// A5 90, 20 bytes: model, firmware minor/major, hardware, serial.
struct DeviceInfo {
  std::uint8_t model_code = 0;
  std::uint8_t firmware_major = 0;  // low byte of the 2-byte firmware field
  std::uint8_t firmware_minor = 0;  // high byte
  std::uint8_t hardware = 0;
  std::array<std::uint8_t, 16> serial{};

  friend bool operator==(const DeviceInfo&, const DeviceInfo&) = default;
};
inline constexpr std::size_t kDeviceInfoSize = 20;
std::array<std::uint8_t, kDeviceInfoSize> encode_device_info(const DeviceInfo& info);
std::optional<DeviceInfo> parse_device_info(std::span<const std::uint8_t> payload);
// The serial as the vendor tools print it: each byte in hex without padding (digits 0-9 print as is).
std::string serial_string(const DeviceInfo& info);

// A5 92 (G1) and A5 91 (G6/TG), 3 bytes: status byte then a u16 error code.
// G1: the status byte is one bit per module (G1Health* below). G6/TG: 0 normal, 1 warning, 2 error.
struct HealthReply {
  std::uint8_t status = 0;
  std::uint16_t error_code = 0;

  friend bool operator==(const HealthReply&, const HealthReply&) = default;
};
inline constexpr std::size_t kHealthSize = 3;
std::array<std::uint8_t, kHealthSize> encode_health(const HealthReply& health);
std::optional<HealthReply> parse_health(std::span<const std::uint8_t> payload);

// G1 health bits: in the A5 92 status byte and in CT information (index 3). 1 = module abnormal.
inline constexpr std::uint8_t kG1HealthSensor = 1u << 0;
inline constexpr std::uint8_t kG1HealthEncoder = 1u << 1;
inline constexpr std::uint8_t kG1HealthPower = 1u << 2;  // wireless power supply
inline constexpr std::uint8_t kG1HealthPd = 1u << 3;     // laser feedback voltage
inline constexpr std::uint8_t kG1HealthLd = 1u << 4;     // laser drive current
inline constexpr std::uint8_t kG1HealthData = 1u << 5;   // no valid point in the lap (blocked)
inline constexpr unsigned kG1HealthBitCount = 6;
// Short name of G1 health bit 0..5 ("sensor", "encoder", ...); "reserved" otherwise.
std::string_view g1_health_bit_name(unsigned bit);

enum class DeviceStatus : std::uint8_t { Normal = 0, Warning = 1, Error = 2 };
// G6/TG status byte; empty for values the manuals do not define.
std::optional<DeviceStatus> device_status(std::uint8_t status);
std::string_view device_status_name(DeviceStatus status);

// A5 09/0A/0B/0C/0D, 4 bytes: u32 little-endian, hundredths of a hertz.
struct ScanFrequency {
  std::uint32_t centihertz = 0;
  double hz() const { return centihertz / 100.0; }

  friend bool operator==(const ScanFrequency&, const ScanFrequency&) = default;
};
inline constexpr std::size_t kScanFrequencySize = 4;
std::array<std::uint8_t, kScanFrequencySize> encode_scan_frequency(ScanFrequency frequency);
std::optional<ScanFrequency> parse_scan_frequency(std::span<const std::uint8_t> payload);

// Every remaining answer is one byte.
inline constexpr std::size_t kOneByteAnswerSize = 1;
std::array<std::uint8_t, 1> encode_one_byte(std::uint8_t value);
std::optional<std::uint8_t> parse_one_byte(std::span<const std::uint8_t> payload);

// A5 D0 / D1: a table index; the table is per model (G1 4..18 kHz, G6/TG 4/8/9 kHz).
// Empty when the payload is not one byte or the index is outside the model's table.
std::optional<std::uint16_t> parse_ranging_khz(const ModelProfile& profile, std::span<const std::uint8_t> payload);

// A5 D9 (toggle): per the manuals 00 = protection now ON, 01 = now OFF.
std::optional<bool> parse_power_down_protection(std::span<const std::uint8_t> payload);
std::array<std::uint8_t, 1> encode_power_down_protection(bool enabled);

// A5 01 answers 01 (low power on), A5 02 answers 00 (off).
std::optional<bool> parse_low_power(std::span<const std::uint8_t> payload);
std::array<std::uint8_t, 1> encode_low_power(bool enabled);

// A5 06/07/08: 00 clockwise, 01 counter-clockwise.
enum class MotorDirection : std::uint8_t { Clockwise = 0, CounterClockwise = 1 };
std::optional<MotorDirection> parse_motor_direction(std::span<const std::uint8_t> payload);
std::array<std::uint8_t, 1> encode_motor_direction(MotorDirection direction);

// A5 0E answers 01 (constant frequency on), A5 0F answers 00 (off).
std::optional<bool> parse_constant_frequency(std::span<const std::uint8_t> payload);
std::array<std::uint8_t, 1> encode_constant_frequency(bool enabled);

// A5 05 (TG): motor and module status. The manual does not define the byte's meaning, so it is
// reported raw.
std::optional<std::uint8_t> parse_module_status(std::span<const std::uint8_t> payload);

}  // namespace ydscope
