#include "core/stream/lap_ring.h"

#include <gtest/gtest.h>

#include <atomic>
#include <thread>

#include "stream/stream_test_support.h"

namespace ydscope {
namespace {

using test::lap_is_consistent;
Lap make_lap(std::uint64_t index, std::size_t points) { return test::indexed_lap(index, points); }

TEST(LapRing, PopsInOrderAndReportsEmpty) {
  LapRing queue(4);
  Lap out;
  EXPECT_FALSE(queue.try_pop(out));
  ASSERT_TRUE(queue.try_push(make_lap(1, 3)));
  ASSERT_TRUE(queue.try_push(make_lap(2, 5)));
  ASSERT_TRUE(queue.try_pop(out));
  EXPECT_EQ(out.index, 1u);
  EXPECT_EQ(out.points.size(), 3u);
  ASSERT_TRUE(queue.try_pop(out));
  EXPECT_EQ(out.index, 2u);
  EXPECT_FALSE(queue.try_pop(out));
}

TEST(LapRing, FullQueueDropsTheNewestAndCountsIt) {
  LapRing queue(2);
  EXPECT_TRUE(queue.try_push(make_lap(1, 1)));
  EXPECT_TRUE(queue.try_push(make_lap(2, 1)));
  EXPECT_FALSE(queue.try_push(make_lap(3, 1)));
  EXPECT_EQ(queue.dropped_full(), 1u);
  Lap out;
  ASSERT_TRUE(queue.try_pop(out));
  EXPECT_EQ(out.index, 1u);  // the queued laps survive; the newest was the one dropped
  EXPECT_TRUE(queue.try_push(make_lap(4, 1)));
}

TEST(LapRing, DrainNewestKeepsTheLastAndCountsTheSkipped) {
  LapRing queue(8);
  for (std::uint64_t i = 1; i <= 5; ++i) ASSERT_TRUE(queue.try_push(make_lap(i, 2)));
  Lap out;
  EXPECT_EQ(queue.drain_newest(out), 5u);
  EXPECT_EQ(out.index, 5u);
  EXPECT_EQ(queue.skipped(), 4u);
  EXPECT_EQ(queue.drain_newest(out), 0u);
  EXPECT_EQ(out.index, 5u);
}

TEST(LapRing, SlotsKeepTheirCapacitySoPushingDoesNotAllocate) {
  LapRing queue(2);
  Lap out;
  ASSERT_TRUE(queue.try_push(make_lap(1, 1000)));
  ASSERT_TRUE(queue.try_pop(out));
  const auto* storage_before = out.points.data();
  ASSERT_TRUE(queue.try_push(make_lap(2, 2000)));
  ASSERT_TRUE(queue.try_pop(out));
  EXPECT_EQ(out.points.data(), storage_before);
  EXPECT_GE(out.points.capacity(), Lap::kMaxPoints);
}

// Two threads hammer the queue; run under ThreadSanitizer in CI. Every lap the producer got in
// must come out once, in order, intact; every lap it could not push must be counted as dropped.
TEST(LapRing, TwoThreadStressLosesNothingUncounted) {
  constexpr std::uint64_t kLaps = 20000;
  LapRing queue(8);
  std::uint64_t pushed = 0;
  std::atomic<bool> done{false};
  std::thread producer([&] {
    for (std::uint64_t i = 0; i < kLaps; ++i) {
      if (queue.try_push(make_lap(i, i % 300 + 1))) ++pushed;
      if (i % 64 == 0) std::this_thread::yield();
    }
    done.store(true, std::memory_order_release);
  });
  std::uint64_t popped = 0;
  std::uint64_t last_index = 0;
  bool ordered = true;
  bool intact = true;
  Lap out;
  auto take = [&] {
    if (popped > 0 && out.index <= last_index) ordered = false;
    if (!lap_is_consistent(out)) intact = false;
    last_index = out.index;
    ++popped;
  };
  while (!done.load(std::memory_order_acquire))
    if (queue.try_pop(out)) take();
  producer.join();
  while (queue.try_pop(out)) take();
  EXPECT_TRUE(ordered);
  EXPECT_TRUE(intact);
  EXPECT_EQ(popped, pushed);
  EXPECT_EQ(pushed + queue.dropped_full(), kLaps);
  EXPECT_GT(popped, 0u);
}

}  // namespace
}  // namespace ydscope
