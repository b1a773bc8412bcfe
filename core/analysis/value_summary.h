#pragma once
// Descriptive statistics of a set of measurements (ranges in mm, lap periods in s): count, mean,
// median, standard deviation, min, max, and a histogram. Plain functions over spans so the sector
// statistics, the lap timing and the report share one implementation.
#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

namespace ydscope {

struct ValueSummary {
  std::size_t count = 0;
  double mean = 0;
  double median = 0;
  double stddev = 0;  // sample standard deviation (n - 1); 0 for fewer than two values
  double min = 0;
  double max = 0;
};

// Reorders `values` (partial sort for the median) to avoid a copy; all zero when empty.
ValueSummary summarize_values(std::span<float> values);
ValueSummary summarize_values(std::span<double> values);

// Robust spread: 1.4826 * median absolute deviation from the median, which equals the standard
// deviation for normal data but ignores a few outliers (a late read, one scheduling hiccup).
// Reorders `values`; 0 for fewer than two values.
double robust_stddev(std::span<double> values);

struct Histogram {
  double lo = 0;  // left edge of the first bin
  double hi = 0;  // right edge of the last bin
  std::vector<std::uint32_t> counts;
  double bin_width() const { return counts.empty() ? 0 : (hi - lo) / static_cast<double>(counts.size()); }
};

// `bins` equal bins over [lo, hi]; values outside are not counted, hi itself falls in the last bin.
// When lo == hi (all values equal) the single value sits in the middle of one bin 1 unit wide.
Histogram make_histogram(std::span<const float> values, double lo, double hi, std::size_t bins);

}  // namespace ydscope
