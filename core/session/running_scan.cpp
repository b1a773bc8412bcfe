#include "core/session/running_scan.h"

#include <algorithm>

#include "core/session/session_counters.h"
#include "core/stream/lap_stream.h"

namespace ydscope {

namespace {
constexpr std::int64_t kKeepalivePeriodNs = 1'000'000'000;  // the manuals allow up to 3 s
}  // namespace

double RunningScan::restart(const ModelProfile& profile, const UnitConventions& conventions) {
  if (decoder_) counters_.close_decoder_epoch();
  decoder_ = std::make_unique<ScanDecoder>(profile, conventions, scale_override_);
  diagnosis_.reset();
  return decoder_->distance_scale();
}

std::optional<double> RunningScan::distance_scale() const {
  return decoder_ ? std::optional(decoder_->distance_scale()) : std::nullopt;
}

LapEndOutlook RunningScan::feed(std::span<const std::uint8_t> bytes, std::int64_t rx_ns) {
  if (!decoder_) return {};
  decoder_->feed(bytes, rx_ns, [this](const Lap& lap) { laps_.publish(lap); });
  const DecoderCounters c = decoder_->counters();
  if (c.packets == 0) diagnosis_.feed(bytes, rx_ns);
  counters_.set_decoder_totals(
      {c.packets, c.zero_packets, c.laps, c.checksum_errors, c.resync_bytes, c.crc_mismatches, c.overflow_points});
  return decoder_->lap_end_outlook();
}

std::optional<std::string> RunningScan::diagnosis(const ModelProfile& expected, std::uint32_t baud) const {
  if (!decoder_ || decoder_->counters().packets > 0) return std::nullopt;
  return diagnosis_.verdict(expected, baud);
}

bool RunningScan::keepalive_due(std::int64_t now_ns) {
  if (now_ns - last_keepalive_ns_ < kKeepalivePeriodNs) return false;
  last_keepalive_ns_ = now_ns;
  return true;
}

std::optional<std::int64_t> RunningScan::stalled_for(std::int64_t now_ns, std::chrono::milliseconds timeout) const {
  const std::int64_t quiet_since = std::max(counters_.last_byte_ns(), scan_started_ns_);
  const std::int64_t quiet_ns = now_ns - quiet_since;
  if (quiet_ns > std::chrono::nanoseconds(timeout).count()) return quiet_ns;
  return std::nullopt;
}

}  // namespace ydscope
