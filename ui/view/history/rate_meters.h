#pragma once
// Rates the panels show: the scan rate measured from lap timestamps, and per-second rates of the
// session's monotonic counters (bytes, packets, laps).
#include <array>
#include <cstddef>
#include <cstdint>
#include <optional>

namespace ydscope::ui {

// Laps per second over the last laps' end times. The lap index counts the laps between two shown
// ones, so laps the UI skipped (drained but not drawn) still count. A gap longer than kMaxGapNs,
// an index going back (a new stream) or a reconnect starts the measurement again.
class ScanRateMeter {
 public:
  static constexpr std::size_t kWindow = 16;
  static constexpr std::int64_t kMaxGapNs = 2'000'000'000;

  void add_lap_end(std::uint64_t lap_index, std::int64_t rx_ns);
  void reset() { count_ = 0; }
  std::optional<double> hz() const;

 private:
  std::array<std::int64_t, kWindow> ends_{};
  std::array<std::uint64_t, kWindow> indices_{};
  std::size_t next_ = 0;
  std::size_t count_ = 0;
};

// Per-second rate of a counter that only grows, from samples taken about once per frame; the rate
// is updated once `period_s` has passed, so the number is steady enough to read.
class CounterRate {
 public:
  explicit CounterRate(double period_s = 1.0) : period_s_(period_s) {}
  void sample(double now_s, std::uint64_t value);
  double per_second() const { return rate_; }

 private:
  double period_s_;
  bool started_ = false;
  double start_s_ = 0.0;
  std::uint64_t start_value_ = 0;
  double rate_ = 0.0;
};

// Mean of the last few frame times or latencies, for a steadier readout.
class RunningMean {
 public:
  void add(double value);
  double mean() const { return count_ ? sum_ / static_cast<double>(count_) : 0.0; }
  double max() const;

 private:
  static constexpr std::size_t kSize = 60;
  std::array<double, kSize> values_{};
  std::size_t next_ = 0;
  std::size_t count_ = 0;
  double sum_ = 0.0;
};

}  // namespace ydscope::ui
