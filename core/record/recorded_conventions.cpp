#include "core/record/recorded_conventions.h"

#include <charconv>
#include <string_view>

namespace ydscope {

namespace {

std::optional<std::uint8_t> byte_of(std::string_view text) {
  unsigned value = 0;
  const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (text.empty() || ec != std::errc() || end != text.data() + text.size() || value > 0xFF) return std::nullopt;
  return static_cast<std::uint8_t>(value);
}

}  // namespace

std::optional<FirmwareVersion> recorded_firmware(const RecordingMetadata& metadata) {
  if (!metadata.firmware) return std::nullopt;
  const std::string_view text = *metadata.firmware;
  const std::size_t dot = text.find('.');
  if (dot == std::string_view::npos) return std::nullopt;
  const auto first = byte_of(text.substr(0, dot));
  const auto second = byte_of(text.substr(dot + 1));
  if (!first || !second) return std::nullopt;
  return FirmwareVersion{*first, *second};
}

std::optional<FirmwareVersion> recorded_sdk_firmware(const RecordingMetadata& metadata) {
  const auto recorded = recorded_firmware(metadata);
  if (!recorded) return std::nullopt;
  return firmware_as_sdk_reads(recorded->major, recorded->minor);
}

const UnitConventions& recorded_conventions(const RecordingMetadata& metadata, const ModelProfile& profile,
                                            std::optional<Reading> asked) {
  if (asked) return conventions_for(profile, recorded_sdk_firmware(metadata), *asked);
  if (metadata.conventions) {
    const UnitConventions* recorded = find_conventions(*metadata.conventions);
    if (recorded && conventions_fit(*recorded, profile)) return *recorded;
  }
  return conventions_for(profile, recorded_sdk_firmware(metadata), Reading::Manual);
}

}  // namespace ydscope
