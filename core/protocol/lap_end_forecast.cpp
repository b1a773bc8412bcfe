#include "core/protocol/lap_end_forecast.h"

#include <algorithm>
#include <cmath>

#include "core/protocol/byte_access.h"
#include "core/protocol/scan_packet.h"

namespace ydscope {

namespace {

// Clockwise angle from `from` to `to`, in [0, 360).
double clockwise(double from, double to) {
  const double d = std::fmod(to - from, 360.0);
  return d < 0 ? d + 360.0 : d;
}

// Strides not counted between a packet's start and the lap end: its own, plus half a stride of
// slack for the motor's wobble, so the short last packet of a lap is never counted as whole.
constexpr double kStridesHeldBack = 1.5;
constexpr std::size_t kSmallestZeroPacket = packet_size(1);
// Lap timing: smoothing weight of a new period, and the slack as jitters and at least 0.3 ms.
constexpr double kPeriodWeight = 0.25;
constexpr double kSlackJitters = 4;
constexpr std::int64_t kLeastSlackNs = 300'000;

}  // namespace

void LapEndForecast::reset() { rhythm_ = {}; }

void LapEndForecast::observe(const PacketView& packet) {
  Rhythm& r = rhythm_;
  const double fsa = raw_angle_degrees(packet.fsa);
  const bool zero = packet.lap_start();
  // A zero packet's own stride (one sample) and the stride into a zero packet (often a short
  // packet) say nothing about ordinary packets.
  if (r.have_last && !r.last_was_zero && !zero) {
    const double stride = clockwise(r.last_fsa, fsa);
    if (stride > 0) {
      r.stride_degrees = stride;
      r.stride_bytes = r.last_size;
    }
  }
  if (zero) {
    r.zero_fsa = fsa;
    r.have_zero = true;
    observe_close(packet.rx_ns);
  }
  r.have_last = true;
  r.last_was_zero = zero;
  r.last_fsa = fsa;
  r.last_size = packet_size(packet.lsn);
}

void LapEndForecast::observe_close(std::int64_t rx_ns) {
  Rhythm& r = rhythm_;
  if (rx_ns <= 0) return;  // no clock (file decoding)
  if (r.last_close_ns > 0 && rx_ns > r.last_close_ns) {
    const auto period = static_cast<double>(rx_ns - r.last_close_ns);
    if (r.period_ns == 0) {
      r.period_ns = period;
      r.jitter_ns = period / 4;  // humble until a few laps have shown their rhythm
    } else {
      // A changed rate (or a lap read late) shows as jitter first, which widens the slack until
      // the estimate has caught up.
      r.jitter_ns += kPeriodWeight * (std::abs(period - r.period_ns) - r.jitter_ns);
      r.period_ns += kPeriodWeight * (period - r.period_ns);
    }
  }
  r.last_close_ns = rx_ns;
}

std::size_t LapEndForecast::bytes_after_packet_at(double fsa_degrees) const {
  const Rhythm& r = rhythm_;
  if (r.stride_degrees == 0 || !r.have_zero) return kSmallestZeroPacket;
  // From the zero packet itself the lap end is a whole turn away.
  const double to_lap_end = fsa_degrees == r.zero_fsa ? 360.0 : clockwise(fsa_degrees, r.zero_fsa);
  const double strides = std::floor(to_lap_end / r.stride_degrees - kStridesHeldBack);
  const std::size_t clear_packets = strides > 0 ? static_cast<std::size_t>(strides) : 0;
  return clear_packets * r.stride_bytes + kSmallestZeroPacket;
}

LapEndOutlook LapEndForecast::outlook(std::span<const std::uint8_t> partial) const {
  const Rhythm& r = rhythm_;
  LapEndOutlook out;
  out.bytes = bytes_to_wait(partial);
  out.packet_bytes = r.stride_bytes;
  if (r.period_ns > 0) {
    out.next_close_ns = r.last_close_ns + static_cast<std::int64_t>(r.period_ns);
    out.close_slack_ns = std::max(kLeastSlackNs, static_cast<std::int64_t>(kSlackJitters * r.jitter_ns));
  }
  return out;
}

std::size_t LapEndForecast::bytes_to_wait(std::span<const std::uint8_t> partial) const {
  const Rhythm& r = rhythm_;
  if (partial.empty()) {
    if (!r.have_last) return 1;
    return bytes_after_packet_at(r.last_fsa);
  }
  if (partial.size() < kPacketHeaderSize) {
    // Its length is not known yet: it may be the smallest zero packet.
    return kSmallestZeroPacket > partial.size() ? kSmallestZeroPacket - partial.size() : 1;
  }
  const std::size_t size = packet_size(partial[3]);
  const std::size_t left = size > partial.size() ? size - partial.size() : 1;
  if (is_lap_start(partial[2])) return left;  // the lap closes with this packet
  const double fsa = raw_angle_degrees(read_u16_le(partial.data() + 4));
  return left + bytes_after_packet_at(fsa);
}

}  // namespace ydscope
