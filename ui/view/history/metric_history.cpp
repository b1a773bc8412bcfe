#include "ui/view/history/metric_history.h"

#include <algorithm>

namespace ydscope::ui {

MetricHistory::MetricHistory(std::size_t capacity) : values_(std::max<std::size_t>(capacity, 1), 0.0f) {}

void MetricHistory::add(float value) {
  values_[next_] = value;
  next_ = (next_ + 1) % values_.size();
  count_ = std::min(count_ + 1, values_.size());
}

void MetricHistory::clear() {
  next_ = 0;
  count_ = 0;
}

std::optional<float> MetricHistory::last() const {
  if (count_ == 0) return std::nullopt;
  return values_[(next_ + values_.size() - 1) % values_.size()];
}

float MetricHistory::min() const {
  if (count_ == 0) return 0.0f;
  return *std::min_element(values_.begin(), values_.begin() + static_cast<std::ptrdiff_t>(count_));
}

float MetricHistory::max() const {
  if (count_ == 0) return 0.0f;
  return *std::max_element(values_.begin(), values_.begin() + static_cast<std::ptrdiff_t>(count_));
}

}  // namespace ydscope::ui
