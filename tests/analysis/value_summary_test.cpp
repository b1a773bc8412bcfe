// The descriptive statistics every other analysis builds on, on values worked out by hand.
#include <gtest/gtest.h>

#include <vector>

#include "core/analysis/value_summary.h"

namespace ydscope {
namespace {

TEST(ValueSummary, OddCountGivesTheMiddleValueAndTheSampleStdDev) {
  std::vector<float> v{5, 1, 4, 2, 3};
  const ValueSummary s = summarize_values(std::span<float>(v));
  EXPECT_EQ(s.count, 5u);
  EXPECT_DOUBLE_EQ(s.mean, 3.0);
  EXPECT_DOUBLE_EQ(s.median, 3.0);
  EXPECT_DOUBLE_EQ(s.min, 1.0);
  EXPECT_DOUBLE_EQ(s.max, 5.0);
  EXPECT_NEAR(s.stddev, 1.5811388, 1e-6);  // sqrt(10 / 4)
}

TEST(ValueSummary, EvenCountAveragesTheTwoMiddleValues) {
  std::vector<double> v{10, 40, 20, 30};
  EXPECT_DOUBLE_EQ(summarize_values(std::span<double>(v)).median, 25.0);
}

TEST(ValueSummary, EmptyAndSingleValues) {
  std::vector<float> none;
  EXPECT_EQ(summarize_values(std::span<float>(none)).count, 0u);
  std::vector<float> one{7};
  const ValueSummary s = summarize_values(std::span<float>(one));
  EXPECT_DOUBLE_EQ(s.median, 7.0);
  EXPECT_DOUBLE_EQ(s.stddev, 0.0);
}

TEST(ValueSummary, RobustStdDevIgnoresAFewOutliersThatThePlainOneDoesNot) {
  // Lap periods of 125 ms, 125 ms +- 0.1 ms, and one 40 ms scheduling hiccup: the deviations
  // from the median are 0 for a third and 0.1 ms for the rest, so their median is 0.1 ms.
  std::vector<double> periods;
  for (int i = 0; i < 60; ++i) periods.push_back(0.125 + (i % 3 - 1) * 1e-4);
  periods.push_back(0.165);
  std::vector<double> copy = periods;
  const double plain = summarize_values(std::span<double>(copy)).stddev;
  const double robust = robust_stddev(std::span<double>(periods));
  EXPECT_NEAR(robust, 1.4826e-4, 1e-7);
  EXPECT_GT(plain, 20 * robust);
}

TEST(Histogram, BinsCoverTheSpanAndTheTopValueFallsInTheLastBin) {
  const std::vector<float> v{0, 0.5f, 1, 2.5f, 4, 9};
  const Histogram h = make_histogram(v, 0, 4, 4);
  ASSERT_EQ(h.counts.size(), 4u);
  EXPECT_DOUBLE_EQ(h.bin_width(), 1.0);
  EXPECT_EQ(h.counts[0], 2u);  // 0, 0.5
  EXPECT_EQ(h.counts[1], 1u);  // 1
  EXPECT_EQ(h.counts[2], 1u);  // 2.5
  EXPECT_EQ(h.counts[3], 1u);  // 4 (the top edge); 9 is outside
}

TEST(Histogram, EqualValuesStillGetABin) {
  const std::vector<float> v{3, 3, 3};
  const Histogram h = make_histogram(v, 3, 3, 5);
  EXPECT_LT(h.lo, 3.0);
  EXPECT_GT(h.hi, 3.0);
  std::uint32_t total = 0;
  for (auto c : h.counts) total += c;
  EXPECT_EQ(total, 3u);
}

}  // namespace
}  // namespace ydscope
