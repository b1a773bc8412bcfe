#pragma once
// LapStream: one producer publishes each lap once; every consumer (the window, a file writer, a
// network bridge, the CLI, a report) reads it from a LapRing of its own, so a slow consumer drops
// only its own laps, and its drops are counted under its name.
//
// Contract: one thread (a session's I/O thread) calls publish(). Any thread may subscribe; the
// subscriber owns the LapSubscription it gets and is the only reader of its ring. Destroying a
// subscription detaches it: once the destructor has returned, the producer neither touches its
// ring nor calls its wake function again, so a consumer can come and go while laps flow. A
// subscription may outlive its stream; it then receives nothing more.
//
// The consumer list sits behind a mutex that only the producer and (un)subscribers take: attach
// and detach happen a few times a run, laps tens of times a second. Readers of laps never take it,
// and publish never waits for a consumer (a full ring drops the newest lap and counts it).
// Nothing is allocated per lap: each ring's slots are laps preallocated at subscribe time.
#include <cstddef>
#include <cstdint>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "core/protocol/lap.h"
#include "core/stream/lap_ring.h"

namespace ydscope {

// One consumer as the app's statistics and the snapshot show it.
struct LapConsumerStats {
  std::string name;
  std::size_t capacity = 0;
  std::uint64_t delivered = 0;  // laps put in its ring
  std::uint64_t dropped = 0;    // laps its full ring could not take
  std::uint64_t skipped = 0;    // laps it took but passed over (drain_newest)
};

class LapStream;

// A consumer's end of the stream. Not copyable or movable: the producer holds its address.
class LapSubscription {
 public:
  using WakeFn = std::function<void()>;
  ~LapSubscription();  // detaches
  LapSubscription(const LapSubscription&) = delete;
  LapSubscription& operator=(const LapSubscription&) = delete;

  const std::string& name() const { return name_; }
  // The ring's consumer side (see LapRing): the oldest lap, or everything with the newest kept.
  bool try_pop(Lap& out) { return ring_.try_pop(out); }
  std::size_t drain_newest(Lap& out) { return ring_.drain_newest(out); }
  std::uint64_t dropped_full() const { return ring_.dropped_full(); }
  std::uint64_t skipped() const { return ring_.skipped(); }
  LapConsumerStats stats() const;

 private:
  friend class LapStream;
  struct Hub;
  LapSubscription(std::shared_ptr<Hub> hub, std::string name, std::size_t capacity, WakeFn wake);
  void deliver(const Lap& lap);  // the producer, under the hub's mutex

  std::shared_ptr<Hub> hub_;
  std::string name_;
  LapRing ring_;
  WakeFn wake_;
};

class LapStream {
 public:
  LapStream();
  ~LapStream();  // detaches every subscription still attached
  LapStream(const LapStream&) = delete;
  LapStream& operator=(const LapStream&) = delete;

  // A new consumer with a ring of `capacity` laps; `wake` runs on the producer's thread after each
  // lap put in its ring (keep it short: it runs while the consumer list is held).
  [[nodiscard]] std::unique_ptr<LapSubscription> subscribe(std::string name, std::size_t capacity,
                                                           LapSubscription::WakeFn wake = {});

  // Producer only: copies `lap` into every consumer's ring and wakes each.
  void publish(const Lap& lap);

  // Any thread: every attached consumer, in the order they subscribed.
  std::vector<LapConsumerStats> stats() const;

 private:
  std::shared_ptr<LapSubscription::Hub> hub_;
};

}  // namespace ydscope
