// The lap stream: every consumer gets every lap in its own ring, a slow one drops only its own
// laps (counted under its name), and consumers come and go while laps flow. The stress tests run
// under ThreadSanitizer in CI.
#include "core/stream/lap_stream.h"

#include <gtest/gtest.h>

#include <atomic>
#include <chrono>
#include <memory>
#include <thread>
#include <vector>

#include "core/allocation_counter.h"
#include "stream/stream_test_support.h"

namespace ydscope {
namespace {

using test::lap_is_consistent;
Lap make_lap(std::uint64_t index) { return test::indexed_lap(index); }

TEST(LapStream, EveryConsumerGetsEveryLapInItsOwnRing) {
  LapStream stream;
  auto window = stream.subscribe("window", 8);
  auto writer = stream.subscribe("writer", 8);
  for (std::uint64_t i = 1; i <= 3; ++i) stream.publish(make_lap(i));
  for (LapSubscription* consumer : {window.get(), writer.get()}) {
    Lap out;
    for (std::uint64_t i = 1; i <= 3; ++i) {
      ASSERT_TRUE(consumer->try_pop(out)) << consumer->name();
      EXPECT_EQ(out.index, i) << consumer->name();
    }
    EXPECT_FALSE(consumer->try_pop(out)) << consumer->name();
  }
}

TEST(LapStream, ASlowConsumerDropsOnlyItsOwnLapsAndTheyAreCountedUnderItsName) {
  LapStream stream;
  auto fast = stream.subscribe("fast", 4);
  auto slow = stream.subscribe("slow", 2);
  Lap out;
  for (std::uint64_t i = 1; i <= 10; ++i) {
    stream.publish(make_lap(i));
    ASSERT_TRUE(fast->try_pop(out));
    EXPECT_EQ(out.index, i);
  }
  const auto stats = stream.stats();
  ASSERT_EQ(stats.size(), 2u);
  EXPECT_EQ(stats[0].name, "fast");
  EXPECT_EQ(stats[0].delivered, 10u);
  EXPECT_EQ(stats[0].dropped, 0u);
  EXPECT_EQ(stats[1].name, "slow");
  EXPECT_EQ(stats[1].capacity, 2u);
  EXPECT_EQ(stats[1].delivered, 2u);
  EXPECT_EQ(stats[1].dropped, 8u);
  ASSERT_TRUE(slow->try_pop(out));
  EXPECT_EQ(out.index, 1u);  // what it had queued survives; the newest laps were the ones dropped
}

TEST(LapStream, WakeRunsOnlyForLapsTheRingTook) {
  LapStream stream;
  int wakes = 0;
  auto consumer = stream.subscribe("bell", 2, [&] { ++wakes; });
  for (std::uint64_t i = 0; i < 5; ++i) stream.publish(make_lap(i));
  EXPECT_EQ(wakes, 2);
  EXPECT_EQ(consumer->dropped_full(), 3u);
}

TEST(LapStream, ADetachedConsumerIsNeitherFedNorWokenAndTheOthersGoOn) {
  LapStream stream;
  int leaving_wakes = 0;
  auto staying = stream.subscribe("staying", 8);
  auto leaving = stream.subscribe("leaving", 8, [&] { ++leaving_wakes; });
  stream.publish(make_lap(1));
  leaving.reset();
  stream.publish(make_lap(2));
  EXPECT_EQ(leaving_wakes, 1);
  const auto stats = stream.stats();
  ASSERT_EQ(stats.size(), 1u);
  EXPECT_EQ(stats[0].name, "staying");
  EXPECT_EQ(stats[0].delivered, 2u);
}

TEST(LapStream, ASubscriptionMayOutliveItsStream) {
  auto stream = std::make_unique<LapStream>();
  auto consumer = stream->subscribe("late", 4);
  stream->publish(make_lap(7));
  stream.reset();
  Lap out;
  ASSERT_TRUE(consumer->try_pop(out));  // what it had received stays readable
  EXPECT_EQ(out.index, 7u);
  EXPECT_FALSE(consumer->try_pop(out));
}

TEST(LapStream, PublishingAndReadingAllocateNothing) {
  LapStream stream;
  auto a = stream.subscribe("a", 4);
  auto b = stream.subscribe("b", 4, [] {});
  std::vector<Lap> laps;
  for (std::uint64_t i = 0; i < 50; ++i) laps.push_back(make_lap(i * 37));  // up to 300 points
  Lap out;
  const std::uint64_t before = test::allocations().calls;
  for (const Lap& lap : laps) {
    stream.publish(lap);
    ASSERT_TRUE(a->try_pop(out));
    ASSERT_EQ(b->drain_newest(out), 1u);
  }
  EXPECT_EQ(test::allocations().calls, before);
  EXPECT_TRUE(lap_is_consistent(out));
}

// One producer and three consumer threads, one of them slow and draining only the newest, while a
// fourth thread attaches and detaches a consumer again and again. Each consumer sees its laps in
// order and intact, and every lap is either taken by it or counted against it; the slow one is
// the one that drops. (The producer here is not paced like a lidar, so a fast consumer may drop
// too; the lap-stream benchmark shows none do at real rates.)
TEST(LapStream, ManyConsumerThreadsWhileConsumersComeAndGo) {
  constexpr std::uint64_t kLaps = 20000;
  LapStream stream;
  std::atomic<bool> producing{true};

  struct Reader {
    std::unique_ptr<LapSubscription> subscription;
    bool slow = false;
    std::uint64_t taken = 0, shown = 0, last_index = 0;
    bool ordered = true, intact = true;
  };
  std::vector<Reader> readers(3);
  readers[0].subscription = stream.subscribe("fast-1", 64);
  readers[1].subscription = stream.subscribe("fast-2", 64);
  readers[2].subscription = stream.subscribe("slow", 4);
  readers[2].slow = true;

  auto read = [&](Reader& r) {
    Lap out;
    auto take = [&](std::size_t taken) {
      if (r.taken > 0 && out.index <= r.last_index) r.ordered = false;
      if (!lap_is_consistent(out)) r.intact = false;
      r.last_index = out.index;
      r.taken += taken;
      r.shown += 1;
    };
    for (;;) {
      const bool last_round = !producing.load(std::memory_order_acquire);
      if (r.slow) {
        const std::size_t taken = r.subscription->drain_newest(out);
        if (taken > 0) take(taken);
        std::this_thread::sleep_for(std::chrono::microseconds(200));
      } else {
        while (r.subscription->try_pop(out)) take(1);
      }
      if (last_round) {  // the producer had finished before this round began
        if (r.slow) {
          const std::size_t taken = r.subscription->drain_newest(out);
          if (taken > 0) take(taken);
        }
        return;
      }
    }
  };
  std::vector<std::thread> threads;
  for (Reader& r : readers) threads.emplace_back(read, std::ref(r));
  std::uint64_t churned = 0;
  std::thread churn([&] {
    while (producing.load(std::memory_order_acquire)) {
      auto passing = stream.subscribe("passing", 2, [] {});
      Lap out;
      while (passing->try_pop(out)) {
        if (!lap_is_consistent(out)) ADD_FAILURE() << "a passing consumer got a torn lap";
      }
      ++churned;
    }
  });
  for (std::uint64_t i = 1; i <= kLaps; ++i) stream.publish(make_lap(i));
  producing.store(false, std::memory_order_release);
  churn.join();
  for (auto& t : threads) t.join();

  for (const Reader& r : readers) {
    const std::string name = r.subscription->name();
    EXPECT_TRUE(r.ordered) << name;
    EXPECT_TRUE(r.intact) << name;
    const LapConsumerStats s = r.subscription->stats();
    EXPECT_EQ(s.delivered + s.dropped, kLaps) << name;  // nothing lost uncounted
    EXPECT_EQ(r.taken, s.delivered) << name;            // everything its ring took came out
    EXPECT_EQ(s.skipped, r.taken - r.shown) << name;    // drain_newest counts what it passed over
    EXPECT_GT(r.taken, 0u) << name;
  }
  const LapConsumerStats slow = readers[2].subscription->stats();
  EXPECT_GT(slow.dropped, 0u) << "the slow consumer was never behind: make it slower";
  EXPECT_GT(churned, 0u);
  EXPECT_EQ(stream.stats().size(), 3u);  // the passing consumers are all gone
}

}  // namespace
}  // namespace ydscope
