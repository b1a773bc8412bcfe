#include "core/sim/faults.h"

namespace ydscope {

std::uint64_t FaultRandom::next() {
  state_ += 0x9E3779B97F4A7C15ULL;
  std::uint64_t z = state_;
  z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ULL;
  z = (z ^ (z >> 27)) * 0x94D049BB133111EBULL;
  return z ^ (z >> 31);
}

bool FaultRandom::chance(double p) {
  if (p <= 0.0) return false;
  if (p >= 1.0) return true;
  const double unit = static_cast<double>(next() >> 11) * 0x1.0p-53;
  return unit < p;
}

std::uint32_t FaultRandom::below(std::uint32_t n) { return n == 0 ? 0 : static_cast<std::uint32_t>(next() % n); }

}  // namespace ydscope
