#include "core/session/read_hold.h"

#include <algorithm>

#include "core/protocol/scan_packet.h"

namespace ydscope {

namespace {
// A device samples at a steady rate, so over tens of milliseconds its stream keeps to the last
// second's average within this margin.
constexpr double kRateMargin = 1.15;
// Shorter holds save less than the timer and the re-registration cost.
constexpr std::chrono::nanoseconds kShortestHold = std::chrono::milliseconds(1);
// n_tty's read buffer (N_TTY_BUF_SIZE): once full, a pty's writer waits and a USB bridge's FIFO
// overflows.
constexpr double kTtyBufferBytes = 4096;
// n_tty throttles the driver once less than this is free (TTY_THRESHOLD_THROTTLE); a bridge's small
// FIFO can overflow from there on, so the throttle point is the real limit.
constexpr double kThrottleRoom = 128;
// Room for what the model leaves out: a USB bridge hands bytes over in bulk packets (64 bytes on a
// full-speed bridge, several queued) rather than evenly at line rate.
constexpr double kMarginBytes = 256;
// How late the hold's timer may end on a loaded machine, the I/O thread waiting for a CPU. On 2
// cores both kept busy, 50 ms timers ended up to 14.8 ms late (p99 7.8 ms); with twice as many busy
// threads as cores, p99 21.5 ms: beyond that no hold short enough to pay for itself could help.
constexpr std::chrono::nanoseconds kTimerLateness = std::chrono::milliseconds(20);
// What a hold may leave to pile up at line rate: the throttle point less the margin and one packet
// that may be waiting already when the hold starts (it arrived while the last chunk was decoded).
constexpr double kHoldBytes = kTtyBufferBytes - kThrottleRoom - kMarginBytes - static_cast<double>(kMaxPacketSize);
}  // namespace

std::chrono::nanoseconds read_hold(const ReadHoldInputs& in) {
  if (in.line_bytes_per_s <= 0) return std::chrono::nanoseconds(0);
  // More than the baud can carry: the port's rate is not the line's (a pseudo-terminal, or a
  // device answering at another baud than it streams). Nothing here bounds what piles up, so
  // read as bytes come.
  if (in.stream_bytes_per_s > in.line_bytes_per_s) return std::chrono::nanoseconds(0);
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
  // The bytes of a late timer count against the same buffer.
  const double late_s = std::chrono::duration<double>(kTimerLateness).count();
  seconds = std::min(seconds, kHoldBytes / in.line_bytes_per_s - late_s);
  const auto hold = std::chrono::nanoseconds(static_cast<std::int64_t>(seconds * 1e9));
  return hold < kShortestHold ? std::chrono::nanoseconds(0) : hold;
}

}  // namespace ydscope
