// The Plots panel's maths (issue 30): round ticks on both axes, the value range a plot shows, the
// sample the cursor read-out names, and the time window that zoom and pause move.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "ui/view/history/plot_readout.h"
#include "ui/view/history/plot_ticks.h"
#include "ui/view/history/plot_window.h"

namespace ydscope::ui {
namespace {

std::vector<double> ticks_of(const AxisTicks& t) { return {t.at.begin(), t.at.begin() + t.count}; }

TEST(PlotTicks, AreRoundStepsThatFitTheAxis) {
  EXPECT_EQ(ticks_of(choose_ticks(0, 1000, 5)), (std::vector<double>{0, 500, 1000})) << "200s would be six ticks";
  EXPECT_EQ(ticks_of(choose_ticks(0, 1000, 6)), (std::vector<double>{0, 200, 400, 600, 800, 1000}));
  // A scan rate near 10 Hz: tenths, labelled with one decimal.
  const AxisTicks hz = choose_ticks(9.55, 10.25, 4);
  EXPECT_EQ(hz.step, 0.2);
  EXPECT_EQ(hz.decimals, 1);
  ASSERT_EQ(hz.count, 4);
  EXPECT_NEAR(hz.at[0], 9.6, 1e-9);
  EXPECT_NEAR(hz.at[3], 10.2, 1e-9);
  // Two minutes back to now, as the time axis counts: whole seconds, a tick at now that is 0, not -0.
  const AxisTicks time = choose_ticks(-120, 0, 7);
  EXPECT_EQ(ticks_of(time), (std::vector<double>{-120, -100, -80, -60, -40, -20, 0}));
  EXPECT_FALSE(std::signbit(time.at[static_cast<std::size_t>(time.count - 1)]));
  EXPECT_EQ(time.decimals, 0);
}

TEST(PlotTicks, NoTicksForAnEmptyRangeAndNeverMoreThanAsked) {
  EXPECT_EQ(choose_ticks(5, 5, 4).count, 0);
  EXPECT_EQ(choose_ticks(1, 0, 4).count, 0);
  for (int max = 1; max <= AxisTicks::kMax; ++max) {
    const AxisTicks t = choose_ticks(-3.7, 1234.5, max);
    EXPECT_GE(t.count, 1) << max;
    EXPECT_LE(t.count, max) << max;
  }
}

TEST(PlotTicks, ValueRangeStartsCountsAtZeroAndCentresAFlatLine) {
  const AxisRange counts = value_range(900, 1000, true);
  EXPECT_EQ(counts.lo, 0.0);
  EXPECT_NEAR(counts.hi, 1150.0, 1e-9);
  const AxisRange flat = value_range(10.0, 10.0, false, 0.2);
  EXPECT_NEAR(flat.lo, 9.8, 1e-9);
  EXPECT_NEAR(flat.hi, 10.2, 1e-9);
  EXPECT_EQ(value_range(0, 0, true).hi, 1.0) << "an empty count plot still has an axis";
}

MetricHistory history(std::initializer_list<float> values, std::size_t capacity = 8) {
  MetricHistory h(capacity);
  for (const float v : values) h.add(v);
  return h;
}

TEST(PlotReadout, NamesTheSampleNearestThePointerInTime) {
  // Ten samples wrapped round a ring of 8: the read-out reads the newest 8, oldest first.
  const MetricHistory times = history({0, 1, 2, 3, 4, 5, 6, 7, 8, 9});
  const MetricHistory values = history({0, 10, 20, 30, 40, 50, 60, 70, 80, 90});
  const auto r = read_at(times, values, 4.4, 1.0);
  ASSERT_TRUE(r);
  EXPECT_EQ(r->time_s, 4.0);
  EXPECT_EQ(r->value, 40.0f);
  EXPECT_EQ(read_at(times, values, 4.6, 1.0)->value, 50.0f);
  EXPECT_EQ(read_at(times, values, 9.3, 1.0)->value, 90.0f);
  EXPECT_FALSE(read_at(times, values, 0.5, 1.0)) << "the ring no longer holds times before 2";
  EXPECT_FALSE(read_at(times, values, 12.0, 1.0)) << "no sample within a second of 12";
  EXPECT_EQ(first_at_or_after(times, 5.5), 4u);
  EXPECT_FALSE(read_at(MetricHistory(4), MetricHistory(4), 1.0, 1.0));
}

TEST(PlotWindow, ShowsWhatIsHeldUpToNowOrThePause) {
  PlotWindow w;
  auto s = w.shown(100.0, 30.0);
  EXPECT_EQ(s.start_s, 70.0);
  EXPECT_EQ(s.end_s, 100.0);
  w.pause(100.0);
  s = w.shown(130.0, 30.0);
  EXPECT_EQ(s.end_s, 100.0) << "a paused plot stays where it was paused";
  w.resume();
  EXPECT_EQ(w.shown(130.0, 30.0).end_s, 130.0);
}

TEST(PlotWindow, ZoomKeepsTheTimeUnderThePointerWhilePaused) {
  PlotWindow w;
  w.pause(100.0);
  w.zoom(0.5, 80.0, 100.0, 40.0);  // showing 60..100, zoom in about 80
  auto s = w.shown(100.0, 40.0);
  EXPECT_DOUBLE_EQ(s.end_s - s.start_s, 20.0);
  EXPECT_DOUBLE_EQ(s.end_s, 90.0);
  EXPECT_NEAR(time_at_x(50.0f, 0.0f, 100.0f, s), 80.0, 1e-9) << "80 s moved off the pointer";
  w.zoom(0.01, 85.0, 100.0, 40.0);
  s = w.shown(100.0, 40.0);
  EXPECT_DOUBLE_EQ(s.end_s - s.start_s, PlotWindow::kMinSpanS);
  w.zoom(1000.0, 85.0, 100.0, 40.0);  // wider than what is held: everything again
  EXPECT_FALSE(w.zoomed());
  EXPECT_EQ(w.shown(100.0, 40.0).start_s, 60.0);
}

TEST(PlotWindow, LiveZoomKeepsNowAtTheRightEdge) {
  PlotWindow w;
  w.zoom(0.25, 70.0, 100.0, 120.0);
  const auto s = w.shown(100.0, 120.0);
  EXPECT_EQ(s.end_s, 100.0);
  EXPECT_DOUBLE_EQ(s.start_s, 70.0);
  EXPECT_FLOAT_EQ(x_at_time(85.0, 0.0f, 300.0f, s), 150.0f);
}

TEST(PlotWindow, WhatIsHeldIsShownInRoundSpansThatGrowInSteps) {
  EXPECT_EQ(round_span_s(0.4), 2.0);
  EXPECT_EQ(round_span_s(2.0), 2.0);
  EXPECT_EQ(round_span_s(2.1), 3.0);
  EXPECT_EQ(round_span_s(7.0), 8.0);
  EXPECT_EQ(round_span_s(13.0), 15.0);
  EXPECT_EQ(round_span_s(100.0), 100.0);
  EXPECT_EQ(round_span_s(101.0), 200.0);
}

TEST(PlotWindow, ALiveSpanStepsByWholePixelColumns) {
  const double column = 120.0 / 300.0;
  const auto at = [&](double now) { return on_whole_columns({now - 120.0, now}, 300.0f); };
  const PlotWindow::Span s = at(1000.05);
  EXPECT_DOUBLE_EQ(s.end_s - s.start_s, 120.0) << "as wide as asked";
  EXPECT_LE(s.end_s, 1000.05);
  EXPECT_GT(s.end_s, 1000.05 - column);
  // Within one column the span is the same to the bit, so a sample sits on the same x.
  const PlotWindow::Span later = at(s.end_s + 0.3 * column);
  EXPECT_EQ(later.start_s, s.start_s);
  EXPECT_EQ(later.end_s, s.end_s);
  EXPECT_EQ(x_at_time(950.0, 0.0f, 300.0f, later), x_at_time(950.0, 0.0f, 300.0f, s));
  // A column on, everything moves one pixel to the left.
  const PlotWindow::Span next = at(s.end_s + 1.2 * column);
  EXPECT_NEAR(next.end_s - s.end_s, column, 1e-9);
  EXPECT_NEAR(x_at_time(950.0, 0.0f, 300.0f, s) - x_at_time(950.0, 0.0f, 300.0f, next), 1.0f, 1e-3f);
  EXPECT_EQ(on_whole_columns({10.0, 5.0}, 300.0f).end_s, 5.0) << "an empty span is left as it is";
}

}  // namespace
}  // namespace ydscope::ui
