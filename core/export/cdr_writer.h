#pragma once
// CdrWriter: XCDR1 little-endian serialisation as ROS 2 (rmw, Fast DDS) writes it: a 4-byte
// encapsulation header (00 01 00 00 = CDR_LE), then each primitive aligned to its own size,
// counted from the end of that header. Strings are a u32 length that includes a terminating NUL;
// sequences a u32 element count, then the elements.
#include <cstddef>
#include <cstdint>
#include <bit>
#include <cstring>
#include <span>
#include <string_view>
#include <vector>

namespace ydscope {

class CdrWriter {
 public:
  explicit CdrWriter(std::vector<std::uint8_t>& out) : out_(out) {
    // The encapsulation header: CDR little-endian, no options. (assign, not insert into the empty
    // vector: GCC 12 warns falsely about that insert at -O2.)
    out_.assign({0x00, 0x01, 0x00, 0x00});
  }

  void u8(std::uint8_t v) { out_.push_back(v); }
  void boolean(bool v) { out_.push_back(v ? 1 : 0); }
  void u32(std::uint32_t v) { primitive(&v, 4); }
  void i32(std::int32_t v) { primitive(&v, 4); }
  void f32(float v) { primitive(&v, 4); }
  void f64(double v) { primitive(&v, 8); }
  void string(std::string_view text) {
    u32(static_cast<std::uint32_t>(text.size() + 1));
    out_.insert(out_.end(), text.begin(), text.end());
    out_.push_back(0);
  }
  void u8_sequence(std::span<const std::uint8_t> bytes) {
    u32(static_cast<std::uint32_t>(bytes.size()));
    out_.insert(out_.end(), bytes.begin(), bytes.end());
  }
  // A float32 sequence: the count, then the values (already 4-aligned after the count).
  void f32_sequence(std::span<const float> values) {
    u32(static_cast<std::uint32_t>(values.size()));
    if (values.empty()) return;  // an empty span may hold no pointer, which memcpy must not get
    const std::size_t at = out_.size();
    out_.resize(at + 4 * values.size());
    std::memcpy(out_.data() + at, values.data(), 4 * values.size());  // host is little-endian (static_assert below)
  }
  // Bytes appended raw, e.g. a PointCloud2 data blob after its u32 count. Returns where they start.
  std::size_t reserve_bytes(std::size_t n) {
    const std::size_t at = out_.size();
    out_.resize(at + n);
    return at;
  }
  std::uint8_t* at(std::size_t offset) { return out_.data() + offset; }
  std::size_t size() const { return out_.size(); }

 private:
  void align(std::size_t n) {
    const std::size_t position = out_.size() - 4;  // alignment origin: after the encapsulation header
    out_.resize(out_.size() + (n - position % n) % n, 0);
  }
  void primitive(const void* v, std::size_t n) {
    align(n);
    const std::size_t at = out_.size();
    out_.resize(at + n);
    std::memcpy(out_.data() + at, v, n);
  }

  std::vector<std::uint8_t>& out_;
};

static_assert(std::endian::native == std::endian::little, "CdrWriter copies host floats as little-endian");

}  // namespace ydscope
