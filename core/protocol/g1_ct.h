#pragma once
// G1's CT information channel. CT bit 0 is the lap start; CT bits 7:1 carry, by the packet's index
// within the lap: 0 (zero packet) the scan frequency, 1 the user version, 3 the health bits (other
// indexes: undocumented production data). A CRC8 over the CT bytes of a lap (zero packet
// included) is sent as one LastCRC byte in front of the next zero packet, so a reader can tell
// whether it saw every packet and may trust the information.
#include <cstdint>
#include <span>

namespace ydscope {

inline constexpr std::size_t kG1CtScanHzIndex = 0;
inline constexpr std::size_t kG1CtVersionIndex = 1;
inline constexpr std::size_t kG1CtHealthIndex = 3;

// One step of the manual's CRC8: reflected polynomial 0x8C, starting value 0 at each zero packet.
constexpr std::uint8_t ct_crc8_update(std::uint8_t crc, std::uint8_t ct) {
  crc = static_cast<std::uint8_t>(crc ^ ct);
  for (int bit = 0; bit < 8; ++bit) crc = static_cast<std::uint8_t>((crc & 1u) ? (crc >> 1) ^ 0x8Cu : crc >> 1);
  return crc;
}

// CRC8 of a whole lap's CT bytes, in received order (zero packet first).
constexpr std::uint8_t ct_crc8(std::span<const std::uint8_t> cts) {
  std::uint8_t crc = 0;
  for (const std::uint8_t ct : cts) crc = ct_crc8_update(crc, ct);
  return crc;
}

// Decoding (the lap-start bit is ignored by each).
inline constexpr double g1_ct_scan_hz(std::uint8_t ct) { return (ct >> 1) / 10.0; }
inline constexpr std::uint8_t g1_ct_version_major(std::uint8_t ct) { return static_cast<std::uint8_t>(ct >> 6); }
inline constexpr std::uint8_t g1_ct_version_minor(std::uint8_t ct) {
  return static_cast<std::uint8_t>((ct >> 1) & 0x1F);
}
inline constexpr std::uint8_t g1_ct_health(std::uint8_t ct) { return static_cast<std::uint8_t>(ct >> 1); }

// Encoding, for the virtual lidar and tests. Values are truncated to the bits the CT has room for
// (scan frequency 0..12.7 Hz in 0.1 Hz, major 0..3, minor 0..31, health 7 bits).
std::uint8_t g1_zero_packet_ct(double scan_hz);  // lap-start bit set
std::uint8_t g1_version_ct(std::uint8_t major, std::uint8_t minor);
std::uint8_t g1_health_ct(std::uint8_t health_bits);

}  // namespace ydscope
