#pragma once
// Every command byte of the G1, G6 and TG-series manuals, and what each one answers.
// A command is the two bytes A5 <code>; which codes a model accepts is in its ModelProfile.
#include <array>
#include <cstdint>
#include <optional>
#include <string_view>

namespace ydscope {

enum class Command : std::uint8_t {
  LowPowerOn = 0x01,      // G6, TG
  LowPowerOff = 0x02,     // G6, TG
  ModuleStatus = 0x05,    // TG: motor and module status
  MotorClockwise = 0x06,  // G6, TG
  MotorCounterClockwise = 0x07,
  MotorDirection = 0x08,
  ScanHzUpTenth = 0x09,    // +0.1 Hz
  ScanHzDownTenth = 0x0A,  // -0.1 Hz
  ScanHzUpOne = 0x0B,      // +1 Hz
  ScanHzDownOne = 0x0C,    // -1 Hz
  ScanHzGet = 0x0D,
  ConstantHzOn = 0x0E,  // G6, TG
  ConstantHzOff = 0x0F,
  RestartG1 = 0x40,
  Scan = 0x60,
  Stop = 0x65,
  RestartG6TG = 0x80,
  DeviceInfo = 0x90,
  HealthStatusCode = 0x91,  // G6, TG: status 0/1/2 + error code
  HealthStatusBits = 0x92,  // G1: one bit per module
  RangingCycle = 0xD0,      // G6, TG: step to the next ranging frequency
  RangingGet = 0xD1,
  PowerDownProtection = 0xD9,  // toggles; the reply says the new state
};

inline constexpr std::uint8_t kCommandStart = 0xA5;

enum class ReplyMode : std::uint8_t { None, Single, Continuous };

// What a command answers: no reply, one reply of a fixed payload length, or a continuous stream.
struct ReplySpec {
  ReplyMode mode;
  std::uint8_t type_code;        // meaningful unless mode == None
  std::uint32_t payload_length;  // Single: exact length; Continuous: 0 (the length field is ignored)
};

ReplySpec reply_spec(Command command);
std::string_view command_name(Command command);
std::array<std::uint8_t, 2> encode_command(Command command);
// The Command for a raw code byte, when it is one the manuals define.
std::optional<Command> command_from_code(std::uint8_t code);

}  // namespace ydscope
