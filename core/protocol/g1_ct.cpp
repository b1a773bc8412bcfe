#include "core/protocol/g1_ct.h"

#include <algorithm>
#include <cmath>

#include "core/protocol/scan_packet.h"

namespace ydscope {

std::uint8_t g1_zero_packet_ct(double scan_hz) {
  const long tenths = std::clamp(std::lround(scan_hz * 10.0), 0L, 127L);
  return static_cast<std::uint8_t>((tenths << 1) | kCtLapStart);
}

std::uint8_t g1_version_ct(std::uint8_t major, std::uint8_t minor) {
  return static_cast<std::uint8_t>(((major & 0x3u) << 6) | ((minor & 0x1Fu) << 1));
}

std::uint8_t g1_health_ct(std::uint8_t health_bits) { return static_cast<std::uint8_t>((health_bits & 0x7Fu) << 1); }

}  // namespace ydscope
