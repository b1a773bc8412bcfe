#pragma once
// RecordTap: the session's records (link bytes both ways, metadata), live, for a consumer thread
// that is not the I/O thread: `record --mcap` and `serve` turn them into MCAP and WebSocket
// messages there, so compression and slow clients never hold up reading the port.
//
// Contract: one producer (the session's I/O thread) calls push(); one consumer calls
// wait_and_take() and hands the records back with recycle() so their buffers are reused (no
// allocation per record in steady state). Bounded by queued payload bytes: when the consumer is
// that far behind, new records are dropped and counted (dropped()), never blocking the producer.
#include <chrono>
#include <condition_variable>
#include <cstdint>
#include <mutex>
#include <optional>
#include <span>
#include <vector>

#include "core/record/recording_format.h"

namespace ydscope {

struct TapRecord {
  RecordType type = RecordType::DeviceToHost;
  std::int64_t t_ns = 0;  // since the tap started (its metadata's start_wall_time), or its epoch
  std::vector<std::uint8_t> payload;
};

class RecordTap {
 public:
  explicit RecordTap(std::size_t max_queued_bytes = 64u << 20) : max_bytes_(max_queued_bytes) {}
  // Times counted from `epoch_ns` (link_clock_ns()) instead of the tap's start: several sessions'
  // taps then share one timeline (one recording of several lidars).
  RecordTap(std::size_t max_queued_bytes, std::int64_t epoch_ns) : max_bytes_(max_queued_bytes), epoch_ns_(epoch_ns) {}
  const std::optional<std::int64_t>& epoch_ns() const { return epoch_ns_; }

  // Producer. False when the record was dropped because the consumer is too far behind.
  bool push(RecordType type, std::span<const std::uint8_t> payload, std::int64_t t_ns);
  // Producer: no more records will come (the session stopped the tap).
  void close();

  // Consumer: waits up to `timeout` for records, then appends every queued one to `out`.
  // False once the tap is closed and empty.
  bool wait_and_take(std::vector<TapRecord>& out, std::chrono::milliseconds timeout);
  // Consumer: gives the records' buffers back (clears `records`).
  void recycle(std::vector<TapRecord>& records);

  std::uint64_t dropped() const;

 private:
  mutable std::mutex mutex_;
  std::condition_variable ready_;
  std::vector<TapRecord> queue_;
  std::vector<TapRecord> free_;
  std::size_t queued_bytes_ = 0;
  std::size_t max_bytes_;
  std::uint64_t dropped_ = 0;
  bool closed_ = false;
  const std::optional<std::int64_t> epoch_ns_;
};

}  // namespace ydscope
