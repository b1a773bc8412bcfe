#include "core/session/recorded_device.h"

#include <optional>

#include "core/record/recorded_conventions.h"

namespace ydscope {
namespace {

// A device field is one byte on the wire: a recording claiming more (a damaged or hand-edited
// file) leaves the field blank rather than showing a wrapped-around value.
std::optional<std::uint8_t> device_byte(std::optional<std::uint32_t> value) {
  if (!value || *value > 0xFF) return std::nullopt;
  return static_cast<std::uint8_t>(*value);
}

}  // namespace

DeviceDetails recorded_device(const RecordingMetadata& metadata, const ModelProfile& profile) {
  DeviceDetails device;
  device.profile = &profile;
  if (const auto code = device_byte(metadata.model_code)) device.model_code = *code;
  if (const auto hardware = device_byte(metadata.hardware)) device.hardware = *hardware;
  if (metadata.serial) device.serial = *metadata.serial;
  if (const auto firmware = recorded_firmware(metadata)) device.firmware = *firmware;
  return device;
}

}  // namespace ydscope
