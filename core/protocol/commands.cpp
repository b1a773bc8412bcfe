#include "core/protocol/commands.h"

namespace ydscope {

namespace {
constexpr std::uint8_t kTypeAnswer = 0x04;  // type code of device info and every one-value answer
constexpr std::uint8_t kTypeHealth = 0x06;
constexpr std::uint8_t kTypeScan = 0x81;
}  // namespace

ReplySpec reply_spec(Command command) {
  switch (command) {
    case Command::Scan: return {ReplyMode::Continuous, kTypeScan, 0};
    case Command::Stop:
    case Command::RestartG1:
    case Command::RestartG6TG: return {ReplyMode::None, 0, 0};
    case Command::DeviceInfo: return {ReplyMode::Single, kTypeAnswer, 20};
    case Command::HealthStatusCode:
    case Command::HealthStatusBits: return {ReplyMode::Single, kTypeHealth, 3};
    case Command::ScanHzUpTenth:
    case Command::ScanHzDownTenth:
    case Command::ScanHzUpOne:
    case Command::ScanHzDownOne:
    case Command::ScanHzGet: return {ReplyMode::Single, kTypeAnswer, 4};
    case Command::LowPowerOn:
    case Command::LowPowerOff:
    case Command::ModuleStatus:
    case Command::MotorClockwise:
    case Command::MotorCounterClockwise:
    case Command::MotorDirection:
    case Command::ConstantHzOn:
    case Command::ConstantHzOff:
    case Command::RangingCycle:
    case Command::RangingGet:
    case Command::PowerDownProtection: return {ReplyMode::Single, kTypeAnswer, 1};
  }
  return {ReplyMode::None, 0, 0};
}

std::string_view command_name(Command command) {
  switch (command) {
    case Command::LowPowerOn: return "low power on";
    case Command::LowPowerOff: return "low power off";
    case Command::ModuleStatus: return "module status";
    case Command::MotorClockwise: return "motor clockwise";
    case Command::MotorCounterClockwise: return "motor counter-clockwise";
    case Command::MotorDirection: return "motor direction";
    case Command::ScanHzUpTenth: return "scan frequency +0.1 Hz";
    case Command::ScanHzDownTenth: return "scan frequency -0.1 Hz";
    case Command::ScanHzUpOne: return "scan frequency +1 Hz";
    case Command::ScanHzDownOne: return "scan frequency -1 Hz";
    case Command::ScanHzGet: return "get scan frequency";
    case Command::ConstantHzOn: return "constant frequency on";
    case Command::ConstantHzOff: return "constant frequency off";
    case Command::RestartG1:
    case Command::RestartG6TG: return "restart";
    case Command::Scan: return "scan";
    case Command::Stop: return "stop";
    case Command::DeviceInfo: return "device info";
    case Command::HealthStatusCode:
    case Command::HealthStatusBits: return "health";
    case Command::RangingCycle: return "next ranging frequency";
    case Command::RangingGet: return "get ranging frequency";
    case Command::PowerDownProtection: return "power-down protection toggle";
  }
  return "unknown";
}

std::array<std::uint8_t, 2> encode_command(Command command) {
  return {kCommandStart, static_cast<std::uint8_t>(command)};
}

std::optional<Command> command_from_code(std::uint8_t code) {
  const auto candidate = static_cast<Command>(code);
  if (command_name(candidate) == "unknown") return std::nullopt;
  return candidate;
}

}  // namespace ydscope
