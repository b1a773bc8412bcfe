#pragma once
// ByteBuffer: a growing little-endian byte string, the way MCAP records are built. Appends only;
// a length written before its content is known is reserved and patched afterwards.
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <span>
#include <string_view>
#include <vector>

namespace ydscope {

class ByteBuffer {
 public:
  void u8(std::uint8_t v) { bytes_.push_back(v); }
  void u16(std::uint16_t v) { little_endian(v, 2); }
  void u32(std::uint32_t v) { little_endian(v, 4); }
  void u64(std::uint64_t v) { little_endian(v, 8); }
  void raw(std::span<const std::uint8_t> data) { bytes_.insert(bytes_.end(), data.begin(), data.end()); }
  void raw(std::string_view text) { bytes_.insert(bytes_.end(), text.begin(), text.end()); }
  // MCAP String: u32 byte length, then the bytes.
  void string(std::string_view text) {
    u32(static_cast<std::uint32_t>(text.size()));
    raw(text);
  }

  // Reserves a u32/u64 slot; patch it once the size is known.
  std::size_t reserve_u32() { return reserve(4); }
  std::size_t reserve_u64() { return reserve(8); }
  void patch_u32(std::size_t at, std::uint32_t v) { patch(at, v, 4); }
  void patch_u64(std::size_t at, std::uint64_t v) { patch(at, v, 8); }

  std::size_t size() const { return bytes_.size(); }
  bool empty() const { return bytes_.empty(); }
  void clear() { bytes_.clear(); }
  const std::uint8_t* data() const { return bytes_.data(); }
  std::span<const std::uint8_t> view() const { return bytes_; }
  std::vector<std::uint8_t>& storage() { return bytes_; }

 private:
  void little_endian(std::uint64_t v, int n) {
    for (int i = 0; i < n; ++i) bytes_.push_back(static_cast<std::uint8_t>(v >> (8 * i)));
  }
  std::size_t reserve(std::size_t n) {
    const std::size_t at = bytes_.size();
    bytes_.resize(at + n);
    return at;
  }
  void patch(std::size_t at, std::uint64_t v, int n) {
    for (int i = 0; i < n; ++i) bytes_[at + static_cast<std::size_t>(i)] = static_cast<std::uint8_t>(v >> (8 * i));
  }

  std::vector<std::uint8_t> bytes_;
};

}  // namespace ydscope
