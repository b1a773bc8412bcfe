#pragma once
// The scan packet of the A5 60 stream, shared by G1, G6 and TG:
//
//   offset 0  AA 55       packet header (u16 0x55AA little-endian)
//          2  CT          bit 0 = lap start (zero packet); G1 puts information in bits 7:1
//          3  LSN         number of 2-byte samples
//          4  FSA (u16)   first sample angle: bit 0 is a check bit that is always 1, angle = (FSA>>1)/64
//          6  LSA (u16)   last sample angle, same layout
//          8  CS  (u16)   XOR of the u16 words 0x55AA, CT|LSN<<8, FSA, LSA and every sample
//         10  samples     LSN little-endian u16
//
// G1 sends one extra byte (LastCRC, see g1_ct.h) in front of every zero packet.
// Encoders here are for tests and the virtual lidar; decoding lives in PacketDecoder.
#include <array>
#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

#include "core/protocol/lap.h"

namespace ydscope {

inline constexpr std::uint8_t kPacketHeader0 = 0xAA;
inline constexpr std::uint8_t kPacketHeader1 = 0x55;
inline constexpr std::uint16_t kPacketHeaderWord = 0x55AA;
inline constexpr std::size_t kPacketHeaderSize = 10;  // up to and including CS
inline constexpr std::size_t kMaxSamplesPerPacket = 255;
inline constexpr std::size_t kMaxPacketSize = kPacketHeaderSize + 2 * kMaxSamplesPerPacket;
inline constexpr std::uint8_t kCtLapStart = 0x01;
// Raw angle units: (raw >> 1) / 64 degrees.
inline constexpr double kAngleUnitsPerDegree = 64.0;

inline constexpr std::size_t packet_size(std::uint8_t lsn) { return kPacketHeaderSize + std::size_t{2} * lsn; }
inline constexpr bool is_lap_start(std::uint8_t ct) { return (ct & kCtLapStart) != 0; }
inline constexpr bool angle_check_bit_ok(std::uint16_t raw_angle) { return (raw_angle & 1u) != 0; }
// First-level angle in degrees, in [0, 512): the manuals' (raw >> 1) / 64.
inline constexpr double raw_angle_degrees(std::uint16_t raw_angle) {
  return static_cast<double>(raw_angle >> 1) / kAngleUnitsPerDegree;
}
// Degrees -> raw angle field with the check bit set; the angle is wrapped into [0, 360).
std::uint16_t encode_raw_angle(double degrees);

// The XOR checksum over a packet's fields; `sample_bytes` are the 2*LSN little-endian sample bytes.
std::uint16_t packet_checksum(std::uint8_t ct, std::uint8_t lsn, std::uint16_t fsa, std::uint16_t lsa,
                              std::span<const std::uint8_t> sample_bytes);

// A scan packet's fields, for building one.
struct ScanPacketSpec {
  std::uint8_t ct = 0;
  std::uint16_t fsa = 1;  // raw fields, check bit included (see encode_raw_angle)
  std::uint16_t lsa = 1;
  std::span<const std::uint16_t> samples;  // 1..255 raw sample words
};

// Writes the packet (header, fields, correct checksum, samples) into `out`, which must hold
// packet_size(samples.size()) bytes; returns the bytes written. Samples beyond 255 are ignored.
std::size_t encode_scan_packet(const ScanPacketSpec& spec, std::span<std::uint8_t> out);
// Appends the packet to `out`.
void append_scan_packet(const ScanPacketSpec& spec, std::vector<std::uint8_t>& out);

// Raw sample word for a range: round(range_mm / distance_scale) << flag_bits | flag, saturated to
// what fits in 16 bits. flag is only kept when flag_bits > 0 (G1).
std::uint16_t encode_sample(double range_mm, PointFlag flag, unsigned flag_bits, double distance_scale);

}  // namespace ydscope
