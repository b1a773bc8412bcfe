#pragma once
// Test helpers for recordings: whole files as bytes, and a .ydrec built byte by byte, so its
// header and record times can say anything a damaged or hostile file might.
#include <cstdint>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

#include "core/record/recording_format.h"

namespace ydscope::test {

inline std::vector<std::uint8_t> read_file_bytes(const std::string& file) {
  std::ifstream in(file, std::ios::binary);
  return std::vector<std::uint8_t>(std::istreambuf_iterator<char>(in), {});
}

inline void write_file_bytes(const std::string& file, const std::vector<std::uint8_t>& bytes) {
  std::ofstream out(file, std::ios::binary | std::ios::trunc);
  out.write(reinterpret_cast<const char*>(bytes.data()), static_cast<std::streamsize>(bytes.size()));
}

class RawRecording {
 public:
  // The file header, then one metadata record of `metadata` (key=value lines) at t=0.
  explicit RawRecording(std::uint16_t version = 1, std::uint16_t header_size = 16,
                        const std::string& metadata = "model=G6\n") {
    auto header = encode_file_header();
    header[12] = static_cast<std::uint8_t>(version);
    header[13] = static_cast<std::uint8_t>(version >> 8);
    header[14] = static_cast<std::uint8_t>(header_size);
    header[15] = static_cast<std::uint8_t>(header_size >> 8);
    bytes_.assign(header.begin(), header.end());
    add(RecordType::Metadata, 0, std::vector<std::uint8_t>(metadata.begin(), metadata.end()));
  }
  // `source`: the header's u16 at byte 2 (version 2's source id, version 1's reserved field).
  void add(RecordType type, std::int64_t t_ns, const std::vector<std::uint8_t>& payload, std::uint16_t source = 0) {
    RecordHeader header;
    header.type = static_cast<std::uint8_t>(type);
    header.source = source;
    header.length = static_cast<std::uint32_t>(payload.size());
    header.t_ns = t_ns;
    const auto head = encode_record_header(header);
    bytes_.insert(bytes_.end(), head.begin(), head.end());
    bytes_.insert(bytes_.end(), payload.begin(), payload.end());
  }
  // One device record per time, each holding its index as a byte.
  void add_device_records(const std::vector<std::int64_t>& times) {
    for (std::size_t i = 0; i < times.size(); ++i)
      add(RecordType::DeviceToHost, times[i], std::vector<std::uint8_t>{static_cast<std::uint8_t>(i)});
  }
  const std::vector<std::uint8_t>& bytes() const { return bytes_; }
  void write(const std::string& path) const { write_file_bytes(path, bytes_); }

 private:
  std::vector<std::uint8_t> bytes_;
};

}  // namespace ydscope::test
