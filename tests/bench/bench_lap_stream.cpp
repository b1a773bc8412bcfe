// The lap stream with many consumers: one producer publishing G6 laps (900 points) at the G6's
// rate (10 laps/s) and at 100 times it, to 1, 3 and 8 consumers, one of which is deliberately slow
// (it takes one lap, then sleeps three lap periods). Prints, per run, each consumer's delivered and
// dropped laps, the cost of one publish (median and p99, on the producer's thread), and the heap
// allocations per lap in the steady state (operator new counted program-wide, after the first
// tenth of the run: a thread's first wait or sleep may allocate once in the C++ runtime).
//
//   bench_lap_stream [--seconds S]   (default 3 s per run; 6 runs)
#include <algorithm>
#include <atomic>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <memory>
#include <string>
#include <thread>
#include <vector>

#include "bench_options.h"
#include "core/allocation_counter.h"
#include "core/stream/lap_stream.h"

namespace {

using namespace ydscope;
using Clock = std::chrono::steady_clock;

Lap g6_lap(std::uint64_t index) {
  Lap lap;
  lap.index = index;
  for (int i = 0; i < 900; ++i)
    lap.points.push_back(
        {static_cast<float>(i) * 0.4f, 1000.0f + static_cast<float>((index + i) % 7000), PointFlag::None});
  return lap;
}

// A consumer thread: the fast ones wait for their wake and take everything; the slow one takes one
// lap and then sleeps for three lap periods.
struct Consumer {
  std::unique_ptr<LapSubscription> subscription;
  std::atomic<std::uint64_t> wakes{0};
  std::uint64_t taken = 0;
  std::thread thread;
};

double percentile(std::vector<double> v, double p) {
  if (v.empty()) return 0;
  std::sort(v.begin(), v.end());
  return v[std::min(v.size() - 1, static_cast<std::size_t>(p * static_cast<double>(v.size())))];
}

void run(double laps_per_s, int consumers, double seconds) {
  LapStream stream;
  std::atomic<bool> done{false};
  const auto period = std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(1.0 / laps_per_s));
  std::vector<std::unique_ptr<Consumer>> all;
  for (int c = 0; c < consumers; ++c) {
    auto consumer = std::make_unique<Consumer>();
    Consumer& me = *consumer;
    const bool slow = c == consumers - 1 && consumers > 1;
    const std::string name = slow ? "slow" : "fast-" + std::to_string(c + 1);
    me.subscription = stream.subscribe(name, 16, [&me] {
      me.wakes.fetch_add(1, std::memory_order_release);
      me.wakes.notify_one();
    });
    me.thread = std::thread([&me, &done, slow, period] {
      Lap lap;
      while (!done.load(std::memory_order_acquire)) {
        const std::uint64_t seen = me.wakes.load(std::memory_order_acquire);
        if (slow) {
          if (me.subscription->try_pop(lap)) ++me.taken;
          std::this_thread::sleep_for(3 * period);
          continue;
        }
        while (me.subscription->try_pop(lap)) ++me.taken;
        me.wakes.wait(seen, std::memory_order_acquire);
      }
      while (me.subscription->try_pop(lap)) ++me.taken;
    });
    all.push_back(std::move(consumer));
  }

  const std::uint64_t laps = static_cast<std::uint64_t>(laps_per_s * seconds);
  std::vector<Lap> source;
  for (std::uint64_t i = 0; i < 64; ++i) source.push_back(g6_lap(i));
  std::vector<double> publish_us;
  publish_us.reserve(laps);
  const std::uint64_t warm_up = laps / 10;
  std::uint64_t allocations_before = 0;
  auto next = Clock::now();
  for (std::uint64_t i = 0; i < laps; ++i) {
    if (i == warm_up) allocations_before = test::allocations().calls;
    std::this_thread::sleep_until(next);
    next += period;
    Lap& lap = source[i % source.size()];
    lap.index = i;
    const auto t0 = Clock::now();
    stream.publish(lap);
    publish_us.push_back(std::chrono::duration<double, std::micro>(Clock::now() - t0).count());
  }
  const std::uint64_t allocations = test::allocations().calls - allocations_before;
  done.store(true, std::memory_order_release);
  for (auto& c : all) {
    c->wakes.fetch_add(1);
    c->wakes.notify_all();
    c->thread.join();
  }

  std::printf("%6.0f laps/s, %d consumer%s: %llu laps, publish median %.1f us p99 %.1f us, %.3f allocations per lap\n",
              laps_per_s, consumers, consumers == 1 ? "" : "s", static_cast<unsigned long long>(laps),
              percentile(publish_us, 0.5), percentile(publish_us, 0.99),
              static_cast<double>(allocations) / static_cast<double>(laps - warm_up));
  for (const auto& c : all) {
    const LapConsumerStats s = c->subscription->stats();
    std::printf("    %-7s delivered %6llu  dropped %6llu  taken %6llu\n", s.name.c_str(),
                static_cast<unsigned long long>(s.delivered), static_cast<unsigned long long>(s.dropped),
                static_cast<unsigned long long>(c->taken));
  }
}

}  // namespace

int main(int argc, char** argv) {
  double seconds = 3;
  ydscope::bench::BenchOptions options("bench_lap_stream", "one producer, 1, 3 and 8 consumers, one of them slow");
  options.add("--seconds", seconds, "how long each case runs");
  options.parse(argc, argv);
  if (!(seconds > 0 && seconds <= 3600)) options.fail("takes --seconds from 0 to 3600");
  for (const double rate : {10.0, 1000.0})
    for (const int consumers : {1, 3, 8}) run(rate, consumers, seconds);
  return 0;
}
