#pragma once
// A minimal CDR (XCDR1 little-endian) reader for the tests: checks the encapsulation header and
// reads primitives with their alignment counted from after it.
#include <cstdint>
#include <cstring>
#include <stdexcept>
#include <string>
#include <vector>

namespace ydscope::test {

class CdrReader {
 public:
  explicit CdrReader(const std::vector<std::uint8_t>& data) : d_(data) {
    if (d_.size() < 4 || d_[0] != 0 || d_[1] != 1) throw std::runtime_error("not CDR_LE");
  }
  std::uint8_t u8() { return take(1)[0]; }
  std::uint32_t u32() {
    std::uint32_t v;
    std::memcpy(&v, take(4, 4), 4);
    return v;
  }
  std::int32_t i32() { return static_cast<std::int32_t>(u32()); }
  float f32() {
    float v;
    std::memcpy(&v, take(4, 4), 4);
    return v;
  }
  std::string str() {
    const std::uint32_t n = u32();
    const std::uint8_t* p = take(n);
    if (n == 0 || p[n - 1] != 0) throw std::runtime_error("CDR string without NUL");
    return std::string(reinterpret_cast<const char*>(p), n - 1);
  }
  std::vector<float> f32s() {
    std::vector<float> v(u32());
    for (auto& x : v) x = f32();
    return v;
  }
  const std::uint8_t* take(std::size_t n, std::size_t align = 1) {
    at_ += (align - (at_ - 4) % align) % align;
    if (at_ + n > d_.size()) throw std::runtime_error("CDR read past the end");
    const std::uint8_t* p = d_.data() + at_;
    at_ += n;
    return p;
  }
  bool at_end() const { return at_ == d_.size(); }

 private:
  const std::vector<std::uint8_t>& d_;
  std::size_t at_ = 4;
};

}  // namespace ydscope::test
