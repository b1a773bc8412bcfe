#include "core/sim/line_pacer.h"

#include <algorithm>
#include <cmath>

namespace ydscope {

LinePacer::LinePacer(std::uint32_t baud) : ns_per_byte_(10.0 * 1e9 / static_cast<double>(baud)) {}

void LinePacer::enqueue(std::int64_t ready_ns, std::span<const std::uint8_t> bytes, std::size_t zero_end,
                        bool is_packet) {
  if (bytes.empty()) return;
  chunks_.push_back({ready_ns, bytes.size(), 0, zero_end, is_packet});
  bytes_.insert(bytes_.end(), bytes.begin(), bytes.end());
}

void LinePacer::drain(std::int64_t now_ns, std::vector<std::uint8_t>& out, std::vector<std::size_t>* zero_ends) {
  const auto now = static_cast<double>(now_ns);
  while (!chunks_.empty()) {
    Chunk& chunk = chunks_.front();
    const double start = std::max(line_free_ns_, static_cast<double>(chunk.ready_ns));
    if (now < start) break;
    const auto fit = static_cast<std::size_t>(std::floor((now - start) / ns_per_byte_ + 1e-9));
    const std::size_t n = std::min(fit, chunk.size - chunk.sent);
    if (n == 0) break;
    const std::size_t base = out.size();
    out.insert(out.end(), bytes_.begin(), bytes_.begin() + static_cast<std::ptrdiff_t>(n));
    bytes_.erase(bytes_.begin(), bytes_.begin() + static_cast<std::ptrdiff_t>(n));
    if (zero_ends && chunk.zero_end != kNoZeroEnd && chunk.zero_end > chunk.sent && chunk.zero_end <= chunk.sent + n)
      zero_ends->push_back(base + (chunk.zero_end - chunk.sent));
    chunk.sent += n;
    line_free_ns_ = start + static_cast<double>(n) * ns_per_byte_;
    if (chunk.sent < chunk.size) break;
    packets_sent_ += chunk.is_packet ? 1 : 0;
    chunks_.pop_front();
  }
}

std::int64_t LinePacer::next_completion_ns() const {
  if (chunks_.empty()) return kNever;
  const Chunk& chunk = chunks_.front();
  const double start = std::max(line_free_ns_, static_cast<double>(chunk.ready_ns));
  return static_cast<std::int64_t>(std::ceil(start + static_cast<double>(chunk.size - chunk.sent) * ns_per_byte_));
}

void LinePacer::drop_unstarted(std::int64_t now_ns) {
  const auto now = static_cast<double>(now_ns);
  double line = line_free_ns_;
  std::size_t keep_chunks = 0;
  std::size_t keep_bytes = 0;
  for (const Chunk& chunk : chunks_) {
    const double start = std::max(line, static_cast<double>(chunk.ready_ns));
    // A chunk partly handed out is in flight whatever the clock says.
    if (chunk.sent == 0 && start >= now) break;
    line = start + static_cast<double>(chunk.size - chunk.sent) * ns_per_byte_;
    ++keep_chunks;
    keep_bytes += chunk.size - chunk.sent;
  }
  chunks_.resize(keep_chunks);
  bytes_.resize(keep_bytes);
}

void LinePacer::clear() {
  chunks_.clear();
  bytes_.clear();
}

}  // namespace ydscope
