#pragma once
// A serial line between two UARTs set to different bauds, for tests of what a host sees at the
// wrong baud (a real line garbles; a pseudo-terminal passes bytes through whatever the baud).
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <vector>

namespace ydscope::test {

// What a receiver at rx_baud reads from a line driven at tx_baud: each byte a 10-bit frame (start
// 0, eight data bits LSB first, stop 1), frames back to back. The receiver finds a falling edge at
// 16x oversampling, samples each bit's middle, and reads a frame whose stop bit is 0 as 0x00 (a
// framing error, as a Linux tty reports it by default).
inline std::vector<std::uint8_t> resample_uart(const std::vector<std::uint8_t>& sent, double tx_baud, double rx_baud) {
  auto level = [&](double t) {
    const auto bit = static_cast<std::size_t>(std::floor(t * tx_baud));
    const std::size_t frame = bit / 10, pos = bit % 10;
    if (frame >= sent.size() || pos == 9) return 1;
    if (pos == 0) return 0;
    return (sent[frame] >> (pos - 1)) & 1;
  };
  const double end = static_cast<double>(sent.size()) * 10 / tx_baud;
  const double bit = 1 / rx_baud;
  std::vector<std::uint8_t> out;
  double t = 0;
  while (t < end) {
    if (level(t) == 1) {
      t += bit / 16;
      continue;
    }
    std::uint8_t byte = 0;
    for (int i = 0; i < 8; ++i)
      if (level(t + (1.5 + i) * bit)) byte = static_cast<std::uint8_t>(byte | (1 << i));
    const bool stop = level(t + 9.5 * bit) == 1;
    out.push_back(stop ? byte : 0);
    t += 9.5 * bit;
    while (!stop && t < end && level(t) == 0) t += bit / 16;  // a break: wait for the line to rise
  }
  return out;
}

}  // namespace ydscope::test
