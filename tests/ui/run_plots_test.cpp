// The Plots panel's history: a ring that reads oldest first, and per-second error counts taken
// from the session's running totals, starting again when those do.
#include <gtest/gtest.h>

#include <utility>
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
  p.add_lap({0.1, std::nullopt, 10.0, 900});  // the meter has no rate yet: no rate point, but the points count
  p.add_lap({0.2, 9.8, 10.0, 910});
  p.add_lap({0.3, 9.9, std::nullopt, 905});  // set value unknown: the line follows the measured one
  EXPECT_EQ(in_order(p.measured_hz()), (std::vector<float>{9.8f, 9.9f}));
  EXPECT_EQ(in_order(p.set_hz()), (std::vector<float>{10.0f, 9.9f}));
  EXPECT_EQ(in_order(p.rate_times()), (std::vector<float>{0.2f, 0.3f}));
  EXPECT_EQ(in_order(p.points()), (std::vector<float>{900, 910, 905}));
  EXPECT_EQ(in_order(p.lap_times()), (std::vector<float>{0.1f, 0.2f, 0.3f}));
  p.clear();
  EXPECT_EQ(p.points().size(), 0u);
  EXPECT_EQ(p.measured_hz().size(), 0u);
  EXPECT_EQ(p.lap_times().size(), 0u);
}

std::vector<std::pair<PlotEventKind, double>> events_of(const RunPlots& p) {
  std::vector<std::pair<PlotEventKind, double>> out;
  for (std::size_t i = 0; i < p.events().size(); ++i) out.emplace_back(p.events().at(i).kind, p.events().at(i).time_s);
  return out;
}

TEST(RunPlots, AStallIsMarkedOnceAtItsTime) {
  // Issue 26: a stall drew as a slow motor. Issue 30: it is marked on the time axis where it
  // happened, once for a run of cut laps.
  RunPlots p;
  p.add_lap({0.9, std::nullopt, 10.0, 400, true});  // the session's first lap starts mid-turn: no stall
  p.add_lap({1.0, 9.9, 10.0, 900});
  p.add_lap({1.1, std::nullopt, 10.0, 310, true});  // cut short by a stall
  p.add_lap({1.9, std::nullopt, 10.0, 120, true});  // the same stall cuts the next one too
  p.add_lap({2.0, std::nullopt, 10.0, 905});        // the meter needs laps again
  p.add_lap({2.1, 10.0, 10.0, 902});
  p.add_lap({5.0, std::nullopt, 10.0, 200, true});  // another stall
  EXPECT_EQ(events_of(p),
            (std::vector<std::pair<PlotEventKind, double>>{{PlotEventKind::Stall, 1.1}, {PlotEventKind::Stall, 5.0}}));
  p.clear();
  EXPECT_EQ(p.events().size(), 0u) << "an event outlived clear()";
}

TEST(RunPlots, RateReconnectAndHealthChangesAreMarked) {
  RunPlots p;
  p.add_lap({1.0, 10.0, 10.0, 900});
  p.add_lap({2.0, 10.0, 10.0, 900});  // the same set value: nothing
  p.add_lap({3.0, 10.0, 8.0, 900});   // set to 8 Hz
  p.sample_counters({3.5, 1000, 0, 0, 0});
  p.sample_counters({3.7, 1000, 0, 0, 1});  // the session reconnected
  p.sample_counters({4.0, 1000, 0, 0, 1});
  p.note_health(HealthSource::HealthAnswer, 0, 4.2);  // the first answer is no change
  p.note_health(HealthSource::CtBits, 0x10, 4.3);     // nor the first of another source
  p.note_health(HealthSource::HealthAnswer, 0, 4.4);
  p.note_health(HealthSource::HealthAnswer, 2 << 16, 4.6);
  EXPECT_EQ(events_of(p), (std::vector<std::pair<PlotEventKind, double>>{{PlotEventKind::RateChange, 3.0},
                                                                         {PlotEventKind::Reconnect, 3.7},
                                                                         {PlotEventKind::HealthChange, 4.6}}));
}

TEST(RunPlots, HeldTimeIsTheOldestSampleOfAnySeries) {
  RunPlots p;
  EXPECT_EQ(p.held_s(10.0), 0.0);
  p.add_lap({4.0, std::nullopt, std::nullopt, 900});
  p.sample_counters({3.0, 0, 0, 0});
  p.sample_counters({4.5, 0, 0, 0});
  EXPECT_DOUBLE_EQ(p.held_s(10.0), 6.0);
}

}  // namespace
}  // namespace ydscope::ui
