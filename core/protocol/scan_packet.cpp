#include "core/protocol/scan_packet.h"

#include <algorithm>
#include <cmath>

#include "core/protocol/byte_access.h"

namespace ydscope {

namespace {
constexpr long kUnitsPerTurn = 360L * 64L;
}

std::uint16_t encode_raw_angle(double degrees) {
  long units = std::lround(degrees * kAngleUnitsPerDegree) % kUnitsPerTurn;
  if (units < 0) units += kUnitsPerTurn;
  return static_cast<std::uint16_t>((units << 1) | 1);
}

std::uint16_t packet_checksum(std::uint8_t ct, std::uint8_t lsn, std::uint16_t fsa, std::uint16_t lsa,
                              std::span<const std::uint8_t> sample_bytes) {
  std::uint16_t cs = kPacketHeaderWord;
  cs ^= static_cast<std::uint16_t>(ct | (lsn << 8));
  cs ^= fsa;
  cs ^= lsa;
  for (std::size_t i = 0; i + 1 < sample_bytes.size(); i += 2) cs ^= read_u16_le(sample_bytes.data() + i);
  return cs;
}

std::size_t encode_scan_packet(const ScanPacketSpec& spec, std::span<std::uint8_t> out) {
  const std::size_t count = std::min(spec.samples.size(), kMaxSamplesPerPacket);
  const auto lsn = static_cast<std::uint8_t>(count);
  const std::size_t size = packet_size(lsn);
  if (out.size() < size) return 0;
  std::uint8_t* p = out.data();
  p[0] = kPacketHeader0;
  p[1] = kPacketHeader1;
  p[2] = spec.ct;
  p[3] = lsn;
  write_u16_le(p + 4, spec.fsa);
  write_u16_le(p + 6, spec.lsa);
  for (std::size_t i = 0; i < count; ++i) write_u16_le(p + kPacketHeaderSize + 2 * i, spec.samples[i]);
  write_u16_le(p + 8, packet_checksum(spec.ct, lsn, spec.fsa, spec.lsa, {p + kPacketHeaderSize, 2 * count}));
  return size;
}

void append_scan_packet(const ScanPacketSpec& spec, std::vector<std::uint8_t>& out) {
  const std::size_t count = std::min(spec.samples.size(), kMaxSamplesPerPacket);
  const std::size_t start = out.size();
  out.resize(start + packet_size(static_cast<std::uint8_t>(count)));
  encode_scan_packet(spec, std::span(out).subspan(start));
}

std::uint16_t encode_sample(double range_mm, PointFlag flag, unsigned flag_bits, double distance_scale) {
  const double units = distance_scale > 0 ? std::round(range_mm / distance_scale) : 0.0;
  const double max_units = static_cast<double>((0xFFFFu >> flag_bits));
  const auto raw = static_cast<std::uint32_t>(std::clamp(units, 0.0, max_units));
  const std::uint32_t flag_value = flag_bits > 0 ? (static_cast<std::uint32_t>(flag) & ((1u << flag_bits) - 1)) : 0;
  return static_cast<std::uint16_t>((raw << flag_bits) | flag_value);
}

}  // namespace ydscope
