#pragma once
// Small helpers for the virtual-lidar tests: talk to a VirtualLidar on an injected clock.
#include <cstdint>
#include <initializer_list>
#include <vector>

#include "core/sim/virtual_lidar.h"

namespace ydscope::test {

inline constexpr std::int64_t kMs = 1'000'000;

// Sends bytes at `now`, lets `wait_ns` pass, and returns everything the device sent meanwhile.
inline std::vector<std::uint8_t> exchange(VirtualLidar& lidar, std::initializer_list<std::uint8_t> bytes,
                                          std::int64_t& now, std::int64_t wait_ns = 50 * kMs) {
  const std::vector<std::uint8_t> in(bytes);
  lidar.receive(in, now);
  now += wait_ns;
  std::vector<std::uint8_t> out;
  lidar.produce(now, out);
  return out;
}

// Lets time pass in steps (as a server would), collecting the stream.
inline std::vector<std::uint8_t> run_for(VirtualLidar& lidar, std::int64_t& now, std::int64_t duration_ns,
                                         std::int64_t step_ns = 5 * kMs) {
  std::vector<std::uint8_t> out;
  const std::int64_t end = now + duration_ns;
  while (now < end) {
    now = std::min(end, now + step_ns);
    lidar.produce(now, out);
  }
  return out;
}

inline std::vector<std::uint8_t> bytes(std::initializer_list<std::uint8_t> list) { return list; }

}  // namespace ydscope::test
