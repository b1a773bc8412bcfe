#include "core/link/read_hold.h"

#include <algorithm>

#include "core/protocol/scan_packet.h"

namespace ydscope {

namespace {
// A device samples at a steady rate, so over tens of milliseconds its stream keeps to the last
// second's average within this margin.
constexpr double kRateMargin = 1.15;
// Shorter holds save less than the timer and the re-registration cost.
constexpr std::chrono::nanoseconds kShortestHold = std::chrono::milliseconds(1);
// What n_tty's buffer holds; the flip buffers behind it (16 KiB on a pty, more on a USB port) are
// the margin, so even at full line rate a hold cannot lose a byte.
constexpr double kMostBytesHeld = 4096;
}  // namespace

std::chrono::nanoseconds read_hold(const ReadHoldInputs& in) {
  if (in.line_bytes_per_s <= 0) return std::chrono::nanoseconds(0);
  const auto bytes = static_cast<double>(in.lap_end.bytes);
  // Up to a packet may already be on its way (a USB bridge or the kernel passes bytes on in
  // chunks), so it may arrive at once; the rest comes no faster than the line carries it, nor,
  // over tens of milliseconds, much faster than the stream's average.
  const double burst =
      in.lap_end.packet_bytes > 0 ? static_cast<double>(in.lap_end.packet_bytes) : static_cast<double>(kMaxPacketSize);
  const double paced = std::max(0.0, bytes - burst);
  double seconds = paced / in.line_bytes_per_s;
  if (in.stream_bytes_per_s > 0) seconds = std::max(seconds, paced / (in.stream_bytes_per_s * kRateMargin));
  if (in.lap_end.next_close_ns > 0) {
    const auto due_ns = in.lap_end.next_close_ns - in.lap_end.close_slack_ns - in.now_ns;
    seconds = std::max(seconds, static_cast<double>(due_ns) * 1e-9);
  }
  seconds = std::min(seconds, kMostBytesHeld / in.line_bytes_per_s);
  const auto hold = std::chrono::nanoseconds(static_cast<std::int64_t>(seconds * 1e9));
  return hold < kShortestHold ? std::chrono::nanoseconds(0) : hold;
}

}  // namespace ydscope
