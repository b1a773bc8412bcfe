// The Plots panel's history: a ring that reads oldest first, and per-second error counts taken
// from the session's running totals, starting again when those do.
#include <gtest/gtest.h>

#include <vector>

#include "ui/view/history/run_plots.h"

namespace ydscope::ui {
namespace {

std::vector<float> in_order(const MetricHistory& h) {
  std::vector<float> out;
  for (std::size_t i = 0; i < h.size(); ++i) out.push_back(h.data()[(h.offset() + i) % h.size()]);
  return out;
}

TEST(MetricHistory, KeepsTheNewestSamplesOldestFirst) {
  MetricHistory h(3);
  EXPECT_FALSE(h.last());
  h.add(1);
  h.add(2);
  EXPECT_EQ(in_order(h), (std::vector<float>{1, 2}));
  h.add(3);
  h.add(4);
  h.add(5);
  EXPECT_EQ(in_order(h), (std::vector<float>{3, 4, 5}));
  EXPECT_EQ(h.last(), 5.0f);
  EXPECT_EQ(h.min(), 3.0f);
  EXPECT_EQ(h.max(), 5.0f);
  h.clear();
  EXPECT_EQ(h.size(), 0u);
  EXPECT_EQ(h.max(), 0.0f);
}

TEST(RunPlots, ErrorsArePerSecondDeltasOfTheTotals) {
  RunPlots p;
  p.sample_counters({0.0, 1000, 5, 0});  // a baseline: nothing plotted yet
  p.sample_counters({0.5, 1000, 7, 0});  // not a second yet
  EXPECT_EQ(p.checksum_errors_per_s().size(), 0u);
  p.sample_counters({1.0, 2000, 9, 1});
  p.sample_counters({2.0, 3000, 9, 1});
  EXPECT_EQ(in_order(p.checksum_errors_per_s()), (std::vector<float>{4, 0}));
  EXPECT_EQ(in_order(p.crc8_failures_per_s()), (std::vector<float>{1, 0}));
  EXPECT_EQ(in_order(p.bytes_per_s()), (std::vector<float>{2000, 3000}));
  // A new session's totals start from zero: a new baseline, never a huge negative-wrapped bar.
  p.sample_counters({3.0, 0, 0, 0});
  p.sample_counters({4.0, 500, 2, 0});
  EXPECT_EQ(in_order(p.checksum_errors_per_s()), (std::vector<float>{4, 0, 2}));
}

TEST(RunPlots, SetAndMeasuredRatesAdvanceTogether) {
  RunPlots p;
  p.add_lap({std::nullopt, 10.0, 900});  // the meter has no rate yet: no rate point, but the points count
  p.add_lap({9.8, 10.0, 910});
  p.add_lap({9.9, std::nullopt, 905});  // set value unknown: the line follows the measured one
  EXPECT_EQ(in_order(p.measured_hz()), (std::vector<float>{9.8f, 9.9f}));
  EXPECT_EQ(in_order(p.set_hz()), (std::vector<float>{10.0f, 9.9f}));
  EXPECT_EQ(in_order(p.points()), (std::vector<float>{900, 910, 905}));
  p.clear();
  EXPECT_EQ(p.points().size(), 0u);
  EXPECT_EQ(p.measured_hz().size(), 0u);
}

TEST(RunPlots, AnInterruptionIsMarkedBesideTheLapAndBeforeTheNextRate) {
  // Issue 26: a stall drew as a slow motor. The cut lap has no rate (the meter starts again), is
  // marked where its points sit, and the first rate after it carries the mark too.
  RunPlots p;
  p.add_lap({9.9, 10.0, 900});
  p.add_lap({std::nullopt, 10.0, 310, true});  // cut short by a stall
  p.add_lap({std::nullopt, 10.0, 905});        // the meter needs laps again
  p.add_lap({10.0, 10.0, 902});
  p.add_lap({10.0, 10.0, 901});
  EXPECT_EQ(in_order(p.per_lap_breaks()), (std::vector<float>{0, 1, 0, 0, 0}));
  EXPECT_EQ(in_order(p.measured_hz()), (std::vector<float>{9.9f, 10.0f, 10.0f}));
  EXPECT_EQ(in_order(p.rate_breaks()), (std::vector<float>{0, 1, 0}));
  p.clear();
  p.add_lap({10.0, 10.0, 900});
  EXPECT_EQ(in_order(p.rate_breaks()), (std::vector<float>{0})) << "a break outlived clear()";
}

}  // namespace
}  // namespace ydscope::ui
