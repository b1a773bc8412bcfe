#include "ui/view/history/rate_meters.h"

#include <algorithm>

namespace ydscope::ui {

void ScanRateMeter::add_lap_end(std::uint64_t lap_index, std::int64_t rx_ns) {
  if (count_ > 0) {
    const std::size_t last = (next_ + kWindow - 1) % kWindow;
    if (rx_ns <= ends_[last] || rx_ns - ends_[last] > kMaxGapNs || lap_index <= indices_[last]) count_ = 0;
  }
  ends_[next_] = rx_ns;
  indices_[next_] = lap_index;
  next_ = (next_ + 1) % kWindow;
  count_ = std::min(count_ + 1, kWindow);
}

std::optional<double> ScanRateMeter::hz() const {
  if (count_ < 3) return std::nullopt;  // two intervals at least, so one late lap does not dominate
  const std::size_t newest = (next_ + kWindow - 1) % kWindow;
  const std::size_t oldest = (next_ + kWindow - count_) % kWindow;
  const double span_s = static_cast<double>(ends_[newest] - ends_[oldest]) * 1e-9;
  if (span_s <= 0.0) return std::nullopt;
  return static_cast<double>(indices_[newest] - indices_[oldest]) / span_s;
}

void CounterRate::sample(double now_s, std::uint64_t value) {
  if (!started_ || value < start_value_) {  // first sample, or the counter was reset
    if (started_) rate_ = 0.0;
    started_ = true;
    start_s_ = now_s;
    start_value_ = value;
    return;
  }
  const double elapsed = now_s - start_s_;
  if (elapsed >= period_s_) {
    rate_ = static_cast<double>(value - start_value_) / elapsed;
    start_s_ = now_s;
    start_value_ = value;
  }
}

void RunningMean::add(double value) {
  if (count_ == kSize) sum_ -= values_[next_];
  values_[next_] = value;
  sum_ += value;
  next_ = (next_ + 1) % kSize;
  count_ = std::min(count_ + 1, kSize);
}

double RunningMean::max() const {
  double best = 0.0;
  for (std::size_t i = 0; i < count_; ++i) best = std::max(best, values_[i]);
  return best;
}

}  // namespace ydscope::ui
