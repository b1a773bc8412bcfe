#include "core/session/session_counters.h"

namespace ydscope {

void SessionCounters::set_decoder_totals(const DecoderTotals& totals) {
  current_ = totals;
  packets_.store(base_.packets + totals.packets, std::memory_order_relaxed);
  zero_packets_.store(base_.zero_packets + totals.zero_packets, std::memory_order_relaxed);
  laps_.store(base_.laps + totals.laps, std::memory_order_relaxed);
  checksum_errors_.store(base_.checksum_errors + totals.checksum_errors, std::memory_order_relaxed);
  resync_bytes_.store(base_.resync_bytes + totals.resync_bytes, std::memory_order_relaxed);
  crc8_failures_.store(base_.crc8_failures + totals.crc8_failures, std::memory_order_relaxed);
  cut_points_.store(base_.cut_points + totals.cut_points, std::memory_order_relaxed);
}

void SessionCounters::close_decoder_epoch() {
  base_.packets += current_.packets;
  base_.zero_packets += current_.zero_packets;
  base_.laps += current_.laps;
  base_.checksum_errors += current_.checksum_errors;
  base_.resync_bytes += current_.resync_bytes;
  base_.crc8_failures += current_.crc8_failures;
  base_.cut_points += current_.cut_points;
  current_ = {};
}

void SessionCounters::reset() {
  for (auto* counter :
       {&bytes_received_, &reads_, &bytes_sent_, &drained_bytes_, &reconnects_, &refused_commands_, &packets_,
        &zero_packets_, &laps_, &checksum_errors_, &resync_bytes_, &crc8_failures_, &cut_points_}) {
    counter->store(0, std::memory_order_relaxed);
  }
  last_byte_ns_.store(0, std::memory_order_relaxed);
  for (auto* rate : {&bytes_per_s_, &packets_per_s_, &laps_per_s_}) rate->store(0, std::memory_order_relaxed);
  base_ = {};
  current_ = {};
  last_tick_ns_ = 0;
  tick_bytes_ = tick_packets_ = tick_laps_ = 0;
}

void SessionCounters::tick(std::int64_t now_ns) {
  const std::uint64_t bytes = bytes_received_.load(std::memory_order_relaxed);
  const std::uint64_t packets = packets_.load(std::memory_order_relaxed);
  const std::uint64_t laps = laps_.load(std::memory_order_relaxed);
  if (last_tick_ns_ != 0 && now_ns > last_tick_ns_) {
    const double seconds = static_cast<double>(now_ns - last_tick_ns_) * 1e-9;
    bytes_per_s_.store(static_cast<double>(bytes - tick_bytes_) / seconds, std::memory_order_relaxed);
    packets_per_s_.store(static_cast<double>(packets - tick_packets_) / seconds, std::memory_order_relaxed);
    laps_per_s_.store(static_cast<double>(laps - tick_laps_) / seconds, std::memory_order_relaxed);
  }
  last_tick_ns_ = now_ns;
  tick_bytes_ = bytes;
  tick_packets_ = packets;
  tick_laps_ = laps;
}

CounterSnapshot SessionCounters::read(std::int64_t now_ns) const {
  CounterSnapshot s;
  s.bytes_received = bytes_received_.load(std::memory_order_relaxed);
  s.bytes_sent = bytes_sent_.load(std::memory_order_relaxed);
  s.reads = reads_.load(std::memory_order_relaxed);
  s.packets = packets_.load(std::memory_order_relaxed);
  s.zero_packets = zero_packets_.load(std::memory_order_relaxed);
  s.laps = laps_.load(std::memory_order_relaxed);
  s.checksum_errors = checksum_errors_.load(std::memory_order_relaxed);
  s.resync_bytes = resync_bytes_.load(std::memory_order_relaxed);
  s.crc8_failures = crc8_failures_.load(std::memory_order_relaxed);
  s.cut_points = cut_points_.load(std::memory_order_relaxed);
  s.drained_bytes = drained_bytes_.load(std::memory_order_relaxed);
  s.reconnects = reconnects_.load(std::memory_order_relaxed);
  s.refused_commands = refused_commands_.load(std::memory_order_relaxed);
  s.bytes_per_s = bytes_per_s_.load(std::memory_order_relaxed);
  s.packets_per_s = packets_per_s_.load(std::memory_order_relaxed);
  s.laps_per_s = laps_per_s_.load(std::memory_order_relaxed);
  const std::int64_t last = last_byte_ns_.load(std::memory_order_relaxed);
  if (last != 0) s.seconds_since_last_byte = static_cast<double>(now_ns - last) * 1e-9;
  return s;
}

}  // namespace ydscope
