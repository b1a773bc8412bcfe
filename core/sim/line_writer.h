#pragma once
// The device's bytes on their way out to the host. They are written in pieces that end at each
// zero packet's last byte, so its time stamp is taken just after the write that completed it, and
// at each write a delivery model makes. Bytes the port does not take (no host, or the host reads
// too slowly and its buffer is full) overrun, as on a UART; the laps they belonged to are counted.
// Server thread only.
#include <cstdint>
#include <cstdio>
#include <functional>
#include <string>
#include <vector>

#include "core/sim/sim_endpoint.h"

namespace ydscope {

class LineWriter {
 public:
  using ZeroStampFn = std::function<void(std::int64_t mono_ns, std::uint64_t zero_index)>;

  explicit LineWriter(ZeroStampFn on_zero_packet) : on_zero_packet_(std::move(on_zero_packet)) {}
  ~LineWriter() { close_zero_log(); }
  LineWriter(const LineWriter&) = delete;
  LineWriter& operator=(const LineWriter&) = delete;

  // Also appends "<zero_index> <mono_ns>" lines to `path` (flushed each line). Throws
  // std::runtime_error with one sentence when the file cannot be made.
  void open_zero_log(const std::string& path);
  void close_zero_log();

  struct Totals {
    std::uint64_t written = 0;       // bytes the host can read
    std::uint64_t unheard = 0;       // bytes that overran
    std::uint64_t zero_packets = 0;  // zero packets written whole
    std::uint64_t laps_overrun = 0;  // laps that newly lost bytes
  };
  // zero_ends and piece_ends: offsets in `out` just past each zero packet and each delivery piece.
  Totals write(SimEndpoint* endpoint, const std::vector<std::uint8_t>& out, const std::vector<std::size_t>& zero_ends,
               const std::vector<std::size_t>* piece_ends = nullptr);

 private:
  ZeroStampFn on_zero_packet_;
  std::FILE* zero_log_ = nullptr;
  std::uint64_t zero_index_ = 0;        // zero packets written whole since the start
  std::uint64_t last_overrun_lap_ = 0;  // the last lap that lost bytes, as its index + 1 (0: none)
};

}  // namespace ydscope
