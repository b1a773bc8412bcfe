#pragma once
// LapRing: a fixed-capacity single-producer single-consumer ring of preallocated laps; each
// consumer of a LapStream has one of its own.
//
// Contract: exactly one thread (the I/O thread, through LapStream) calls try_push; exactly one
// other thread (the consumer) calls try_pop / drain_newest. The counters may be read from any
// thread.
// Slots are Laps created up front with their point capacity, and pushing copies into a slot, so
// the steady state allocates nothing. When the ring is full the newest lap is dropped and counted:
// the consumer is behind, and the laps already queued are older but were never shown.
#include <atomic>
#include <cstddef>
#include <cstdint>
#include <new>
#include <vector>

#include "core/protocol/lap.h"

namespace ydscope {

class LapRing {
 public:
  explicit LapRing(std::size_t capacity = 8) : slots_(capacity + 1) {}  // one slot stays empty
  LapRing(const LapRing&) = delete;
  LapRing& operator=(const LapRing&) = delete;

  std::size_t capacity() const { return slots_.size() - 1; }

  // Producer only. False (and counted in dropped_full) when the consumer has not kept up.
  [[nodiscard]] bool try_push(const Lap& lap) {
    const std::size_t head = head_.load(std::memory_order_relaxed);
    const std::size_t next = advance(head);
    if (next == tail_cache_) {
      tail_cache_ = tail_.load(std::memory_order_acquire);
      if (next == tail_cache_) {
        dropped_full_.fetch_add(1, std::memory_order_relaxed);
        return false;
      }
    }
    slots_[head] = lap;  // copy-assign keeps the slot's point capacity
    head_.store(next, std::memory_order_release);
    pushed_.fetch_add(1, std::memory_order_relaxed);
    return true;
  }

  // Consumer only. Moves the oldest queued lap into `out` by copy; false when empty.
  bool try_pop(Lap& out) {
    const std::size_t tail = tail_.load(std::memory_order_relaxed);
    if (tail == head_cache_) {
      head_cache_ = head_.load(std::memory_order_acquire);
      if (tail == head_cache_) return false;
    }
    out = slots_[tail];
    tail_.store(advance(tail), std::memory_order_release);
    return true;
  }

  // Consumer only. Takes everything queued, keeps the newest in `out`, and counts the others as
  // skipped (a frame shows one lap). Returns how many laps were taken; `out` is untouched on 0.
  std::size_t drain_newest(Lap& out) {
    const std::size_t head = head_.load(std::memory_order_acquire);
    std::size_t tail = tail_.load(std::memory_order_relaxed);
    if (tail == head) return 0;
    std::size_t taken = 0;
    std::size_t newest = tail;
    while (tail != head) {
      newest = tail;
      tail = advance(tail);
      ++taken;
    }
    out = slots_[newest];
    tail_.store(tail, std::memory_order_release);
    skipped_.fetch_add(taken - 1, std::memory_order_relaxed);
    return taken;
  }

  std::uint64_t dropped_full() const { return dropped_full_.load(std::memory_order_relaxed); }
  std::uint64_t skipped() const { return skipped_.load(std::memory_order_relaxed); }
  std::uint64_t pushed() const { return pushed_.load(std::memory_order_relaxed); }

 private:
  static constexpr std::size_t kCacheLine = 64;

  std::size_t advance(std::size_t index) const { return index + 1 == slots_.size() ? 0 : index + 1; }

  std::vector<Lap> slots_;
  // Producer and consumer indices on separate cache lines, each with a cached copy of the other's
  // index so the common case touches no shared line.
  alignas(kCacheLine) std::atomic<std::size_t> head_{0};
  std::size_t tail_cache_ = 0;
  alignas(kCacheLine) std::atomic<std::size_t> tail_{0};
  std::size_t head_cache_ = 0;
  alignas(kCacheLine) std::atomic<std::uint64_t> dropped_full_{0};  // the producer's counters
  std::atomic<std::uint64_t> pushed_{0};
  alignas(kCacheLine) std::atomic<std::uint64_t> skipped_{0};  // the consumer's
};

}  // namespace ydscope
