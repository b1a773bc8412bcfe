#include "core/protocol/health_level.h"

#include "core/protocol/reply.h"

namespace ydscope {

namespace {
constexpr std::uint8_t kG1ModuleBits = (1u << kG1HealthBitCount) - 1;
}  // namespace

HealthLevel health_bits_level(std::uint8_t bits) {
  return (bits & kG1ModuleBits) != 0 ? HealthLevel::Error : HealthLevel::Ok;
}

HealthLevel health_status_level(std::uint8_t status, std::uint16_t error_code) {
  const auto known = device_status(status);
  if (!known || *known == DeviceStatus::Error) return HealthLevel::Error;
  if (*known == DeviceStatus::Warning || error_code != 0) return HealthLevel::Warning;
  return HealthLevel::Ok;
}

HealthLevel health_level(Command command, std::uint8_t status, std::uint16_t error_code) {
  return command == Command::HealthStatusBits ? health_bits_level(status) : health_status_level(status, error_code);
}

std::string_view health_level_name(HealthLevel level) {
  switch (level) {
    case HealthLevel::Ok: return "ok";
    case HealthLevel::Warning: return "warning";
    case HealthLevel::Error: return "error";
  }
  return "unknown";
}

}  // namespace ydscope
