#pragma once
// Live counters of a device session. Written by the I/O thread only (relaxed atomics, no locks on
// the byte path); read from any thread as a plain CounterSnapshot (core/snapshot). Rates are
// recomputed by the I/O thread once a second from the totals, so reading them costs nothing.
#include <atomic>
#include <cstdint>

#include "core/snapshot/counter_snapshot.h"

namespace ydscope {

class SessionCounters {
 public:
  // I/O thread.
  void add_received(std::uint64_t n, std::int64_t now_ns) {
    bump(bytes_received_, n);
    bump(reads_, 1);
    last_byte_ns_.store(now_ns, std::memory_order_relaxed);
  }
  void add_sent(std::uint64_t n) { bump(bytes_sent_, n); }
  void add_drained(std::uint64_t n) { bump(drained_bytes_, n); }
  void add_reconnect() { bump(reconnects_, 1); }
  void add_refused() { bump(refused_commands_, 1); }
  // The decoder's totals for the current link are added to what earlier links decoded.
  struct DecoderTotals {
    std::uint64_t packets = 0, zero_packets = 0, laps = 0, checksum_errors = 0, resync_bytes = 0, crc8_failures = 0,
                  cut_points = 0;
  };
  void set_decoder_totals(const DecoderTotals& totals);
  // Folds the current link's decoder totals into the base before a new decoder starts at zero.
  void close_decoder_epoch();
  // A new connection: its counts start at zero (a reconnect within one connection keeps them).
  void reset();
  // Once a second: recompute the rates from the totals.
  void tick(std::int64_t now_ns);

  // Any thread.
  CounterSnapshot read(std::int64_t now_ns) const;
  std::int64_t last_byte_ns() const { return last_byte_ns_.load(std::memory_order_relaxed); }
  double bytes_per_s() const { return bytes_per_s_.load(std::memory_order_relaxed); }

 private:
  static void bump(std::atomic<std::uint64_t>& counter, std::uint64_t n) {
    counter.store(counter.load(std::memory_order_relaxed) + n, std::memory_order_relaxed);
  }

  std::atomic<std::uint64_t> bytes_received_{0}, reads_{0}, bytes_sent_{0}, drained_bytes_{0}, reconnects_{0},
      refused_commands_{0};
  std::atomic<std::uint64_t> packets_{0}, zero_packets_{0}, laps_{0}, checksum_errors_{0}, resync_bytes_{0},
      crc8_failures_{0}, cut_points_{0};
  std::atomic<std::int64_t> last_byte_ns_{0};
  std::atomic<double> bytes_per_s_{0}, packets_per_s_{0}, laps_per_s_{0};
  // I/O thread only.
  DecoderTotals base_{};
  DecoderTotals current_{};
  std::int64_t last_tick_ns_ = 0;
  std::uint64_t tick_bytes_ = 0, tick_packets_ = 0, tick_laps_ = 0;
};

}  // namespace ydscope
