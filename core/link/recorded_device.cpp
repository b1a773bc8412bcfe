#include "core/link/recorded_device.h"

#include <charconv>
#include <optional>
#include <string_view>

namespace ydscope {
namespace {

// A device field is one byte on the wire: a recording claiming more (a damaged or hand-edited
// file) leaves the field blank rather than showing a wrapped-around value.
std::optional<std::uint8_t> device_byte(std::optional<std::uint32_t> value) {
  if (!value || *value > 0xFF) return std::nullopt;
  return static_cast<std::uint8_t>(*value);
}

std::optional<std::uint8_t> device_byte(std::string_view text) {
  unsigned value = 0;
  const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (ec != std::errc() || end != text.data() + text.size() || text.empty() || value > 0xFF) return std::nullopt;
  return static_cast<std::uint8_t>(value);
}

}  // namespace

DeviceDetails recorded_device(const RecordingMetadata& metadata, const ModelProfile& profile) {
  DeviceDetails device;
  device.profile = &profile;
  if (const auto code = device_byte(metadata.model_code)) device.model_code = *code;
  if (const auto hardware = device_byte(metadata.hardware)) device.hardware = *hardware;
  if (metadata.serial) device.serial = *metadata.serial;
  if (metadata.firmware) {  // "major.minor"
    const std::string_view text = *metadata.firmware;
    const std::size_t dot = text.find('.');
    const auto major = device_byte(text.substr(0, dot));
    const auto minor = dot == std::string_view::npos ? std::nullopt : device_byte(text.substr(dot + 1));
    if (major && minor) device.firmware = {*major, *minor};
  }
  return device;
}

}  // namespace ydscope
