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

// A single reply written out as the manuals give it (A5 5A, u32 length | mode 0 << 30, type code,
// payload), not built with the encoders under test.
inline std::vector<std::uint8_t> single_reply(std::uint8_t length, std::uint8_t type,
                                              const std::vector<std::uint8_t>& payload) {
  std::vector<std::uint8_t> out = {0xA5, 0x5A, length, 0x00, 0x00, 0x00, type};
  for (const std::uint8_t byte : payload) out.push_back(byte);  // (insert trips a GCC 12 false warning)
  return out;
}
// The scan frequency replies (A5 09/0B/0D...): 4 bytes, hundredths of a hertz.
inline std::vector<std::uint8_t> scan_hz_reply(std::uint32_t centihz) {
  return single_reply(0x04, 0x04,
                      {static_cast<std::uint8_t>(centihz & 0xFF), static_cast<std::uint8_t>(centihz >> 8),
                       static_cast<std::uint8_t>(centihz >> 16), static_cast<std::uint8_t>(centihz >> 24)});
}
inline const std::vector<std::uint8_t> kNoReply;
// The reply header that opens a scan (continuous mode, type 81).
inline const std::vector<std::uint8_t> kScanHeader{0xA5, 0x5A, 0x05, 0x00, 0x00, 0x40, 0x81};

inline bool is_tg(Model m) { return m == Model::TG15 || m == Model::TG30 || m == Model::TG50; }

}  // namespace ydscope::test
