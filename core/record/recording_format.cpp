#include "core/record/recording_format.h"

#include <algorithm>

#include "core/protocol/byte_access.h"

namespace ydscope {
namespace {

void write_i64_le(std::uint8_t* p, std::int64_t value) {
  const auto bits = static_cast<std::uint64_t>(value);
  write_u32_le(p, static_cast<std::uint32_t>(bits & 0xFFFFFFFFu));
  write_u32_le(p + 4, static_cast<std::uint32_t>(bits >> 32));
}

std::int64_t read_i64_le(const std::uint8_t* p) {
  const std::uint64_t bits = read_u32_le(p) | (static_cast<std::uint64_t>(read_u32_le(p + 4)) << 32);
  return static_cast<std::int64_t>(bits);
}

}  // namespace

bool is_recording(std::span<const std::uint8_t> first_bytes) {
  return first_bytes.size() >= kRecordingMagic.size() &&
         std::equal(kRecordingMagic.begin(), kRecordingMagic.end(), first_bytes.begin());
}

std::array<std::uint8_t, kFileHeaderSize> encode_file_header(std::uint16_t version) {
  std::array<std::uint8_t, kFileHeaderSize> bytes{};
  std::copy(kRecordingMagic.begin(), kRecordingMagic.end(), bytes.begin());
  write_u16_le(bytes.data() + 12, version);
  write_u16_le(bytes.data() + 14, static_cast<std::uint16_t>(kFileHeaderSize));
  return bytes;
}

std::optional<FileHeader> parse_file_header(std::span<const std::uint8_t, kFileHeaderSize> bytes) {
  if (!is_recording(bytes)) return std::nullopt;
  FileHeader header;
  header.version = read_u16_le(bytes.data() + 12);
  header.header_size = read_u16_le(bytes.data() + 14);
  return header;
}

std::array<std::uint8_t, kRecordHeaderSize> encode_record_header(const RecordHeader& header) {
  std::array<std::uint8_t, kRecordHeaderSize> bytes{};
  bytes[0] = header.type;
  bytes[1] = header.flags;
  write_u16_le(bytes.data() + 2, header.source);
  write_u32_le(bytes.data() + 4, header.length);
  write_i64_le(bytes.data() + 8, header.t_ns);
  return bytes;
}

RecordHeader parse_record_header(std::span<const std::uint8_t, kRecordHeaderSize> bytes) {
  RecordHeader header;
  header.type = bytes[0];
  header.flags = bytes[1];
  header.source = read_u16_le(bytes.data() + 2);
  header.length = read_u32_le(bytes.data() + 4);
  header.t_ns = read_i64_le(bytes.data() + 8);
  return header;
}

}  // namespace ydscope
