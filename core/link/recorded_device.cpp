#include "core/link/recorded_device.h"

#include <cstdio>

namespace ydscope {

DeviceDetails recorded_device(const RecordingMetadata& metadata, const ModelProfile& profile) {
  DeviceDetails device;
  device.profile = &profile;
  if (metadata.model_code) device.model_code = static_cast<std::uint8_t>(*metadata.model_code);
  if (metadata.hardware) device.hardware = static_cast<std::uint8_t>(*metadata.hardware);
  if (metadata.serial) device.serial = *metadata.serial;
  unsigned major = 0, minor = 0;
  if (metadata.firmware && std::sscanf(metadata.firmware->c_str(), "%u.%u", &major, &minor) == 2) {
    device.firmware.major = static_cast<std::uint8_t>(major);
    device.firmware.minor = static_cast<std::uint8_t>(minor);
  }
  return device;
}

}  // namespace ydscope
