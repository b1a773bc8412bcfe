#include "core/sim/line_writer.h"

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <span>
#include <stdexcept>

#include "core/sim/sim_server.h"

namespace ydscope {

void LineWriter::open_zero_log(const std::string& path) {
  close_zero_log();
  zero_log_ = std::fopen(path.c_str(), "w");
  if (!zero_log_) throw std::runtime_error("could not open the zero-packet log " + path + ": " + std::strerror(errno));
}

void LineWriter::close_zero_log() {
  if (zero_log_) std::fclose(zero_log_);
  zero_log_ = nullptr;
}

LineWriter::Totals LineWriter::write(SimEndpoint* endpoint, const std::vector<std::uint8_t>& out,
                                     const std::vector<std::size_t>& zero_ends,
                                     const std::vector<std::size_t>* piece_ends) {
  Totals totals;
  std::size_t pos = 0;
  const auto write_piece = [&](std::size_t end) {
    const std::span<const std::uint8_t> piece(out.data() + pos, end - pos);
    const std::size_t sent = endpoint ? endpoint->send(piece) : 0;
    totals.written += sent;
    pos = end;
    // A zero packet cut short is not counted as written, so its lap runs on to the next one.
    if (sent < piece.size() && zero_index_ > 0 && last_overrun_lap_ != zero_index_) {
      last_overrun_lap_ = zero_index_;
      ++totals.laps_overrun;
    }
    return sent == piece.size();
  };
  std::size_t next_zero = 0;
  std::size_t next_piece = 0;
  const std::size_t pieces = piece_ends ? piece_ends->size() : 0;
  while (next_zero < zero_ends.size() || next_piece < pieces) {
    const std::size_t zero_end = next_zero < zero_ends.size() ? zero_ends[next_zero] : out.size() + 1;
    const std::size_t piece_end = next_piece < pieces ? (*piece_ends)[next_piece] : out.size() + 1;
    const std::size_t end = std::min(zero_end, piece_end);
    if (piece_end == end) ++next_piece;
    if (zero_end != end) {
      if (end > pos) write_piece(end);
      continue;
    }
    ++next_zero;
    if (!write_piece(end)) continue;
    const std::int64_t stamp = monotonic_ns();
    const std::uint64_t index = zero_index_++;
    ++totals.zero_packets;
    if (on_zero_packet_) on_zero_packet_(stamp, index);
    if (zero_log_) {
      std::fprintf(zero_log_, "%llu %lld\n", static_cast<unsigned long long>(index), static_cast<long long>(stamp));
      std::fflush(zero_log_);
    }
  }
  if (pos < out.size()) write_piece(out.size());
  totals.unheard = out.size() - totals.written;
  return totals;
}

}  // namespace ydscope
