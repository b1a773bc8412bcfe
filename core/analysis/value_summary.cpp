#include "core/analysis/value_summary.h"

#include <algorithm>
#include <cmath>

namespace ydscope {

namespace {

template <typename T>
ValueSummary summarize(std::span<T> values) {
  ValueSummary s;
  s.count = values.size();
  if (values.empty()) return s;
  double sum = 0;
  double lo = values[0], hi = values[0];
  for (const T v : values) {
    sum += static_cast<double>(v);
    lo = std::min(lo, static_cast<double>(v));
    hi = std::max(hi, static_cast<double>(v));
  }
  s.mean = sum / static_cast<double>(values.size());
  s.min = lo;
  s.max = hi;
  if (values.size() > 1) {
    // Two passes (mean first) keep the variance exact for ranges of tens of metres in mm.
    double squares = 0;
    for (const T v : values) squares += (static_cast<double>(v) - s.mean) * (static_cast<double>(v) - s.mean);
    s.stddev = std::sqrt(squares / static_cast<double>(values.size() - 1));
  }
  const std::size_t mid = values.size() / 2;
  std::nth_element(values.begin(), values.begin() + static_cast<std::ptrdiff_t>(mid), values.end());
  double median = static_cast<double>(values[mid]);
  if (values.size() % 2 == 0) {
    const T below = *std::max_element(values.begin(), values.begin() + static_cast<std::ptrdiff_t>(mid));
    median = 0.5 * (median + static_cast<double>(below));
  }
  s.median = median;
  return s;
}

}  // namespace

ValueSummary summarize_values(std::span<float> values) { return summarize(values); }
ValueSummary summarize_values(std::span<double> values) { return summarize(values); }

double robust_stddev(std::span<double> values) {
  if (values.size() < 2) return 0;
  const double median = summarize_values(values).median;
  for (double& v : values) v = std::fabs(v - median);
  return 1.4826 * summarize_values(values).median;
}

Histogram make_histogram(std::span<const float> values, double lo, double hi, std::size_t bins) {
  Histogram h;
  if (bins == 0) return h;
  if (!(hi > lo)) {
    lo -= 0.5;
    hi = lo + 1.0;
  }
  h.lo = lo;
  h.hi = hi;
  h.counts.assign(bins, 0);
  const double scale = static_cast<double>(bins) / (hi - lo);
  for (const float v : values) {
    const double x = static_cast<double>(v);
    if (x < lo || x > hi) continue;
    const auto bin = std::min(bins - 1, static_cast<std::size_t>((x - lo) * scale));
    ++h.counts[bin];
  }
  return h;
}

}  // namespace ydscope
