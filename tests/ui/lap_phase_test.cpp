#include <gtest/gtest.h>

#include "ui/view/scene/colour_map.h"
#include "ui/view/window/frame_pacing.h"
#include "ui/view/scene/lap_history.h"
#include "ui/view/scene/lap_phase.h"
#include "tests/ui/faded_cloud.h"
#include "ui/view/scene/point_cloud.h"
#include "ui/view/scene/source_clouds.h"

namespace ydscope::ui {
namespace {

TEST(LapPhase, RisesFromZeroToOneOverTheLapPeriodAndHoldsWhileTheNextLapIsLate) {
  LapPhase phase;
  EXPECT_EQ(phase.at(5.0), 0.0f) << "no lap yet";
  phase.on_lap(1.0);
  EXPECT_EQ(phase.at(1.05), 0.0f) << "one lap gives no period";
  phase.on_lap(1.125);  // a G6 at 8 Hz
  EXPECT_NEAR(phase.period_s(), 0.125, 1e-9);
  EXPECT_NEAR(phase.at(1.125), 0.0f, 1e-6);
  EXPECT_NEAR(phase.at(1.1875), 0.5f, 1e-4);
  EXPECT_EQ(phase.at(1.5), 1.0f) << "a late lap holds the phase at 1";
}

TEST(LapPhase, FollowsARateChangeWithinAFewLapsButNotOneLateLap) {
  LapPhase phase;
  double t = 0.0;
  for (int i = 0; i < 20; ++i) phase.on_lap(t += 0.1);
  phase.on_lap(t += 0.3);  // one late lap (a stalled frame upstream)
  EXPECT_LT(phase.period_s(), 0.16) << "one late lap barely moves the period";
  for (int i = 0; i < 20; ++i) phase.on_lap(t += 0.2);  // the scan rate went from 10 to 5 Hz
  EXPECT_NEAR(phase.period_s(), 0.2, 0.005);
}

TEST(LapPhase, AGapOfSecondsOrAResetForgetsThePeriod) {
  LapPhase phase;
  phase.on_lap(0.0);
  phase.on_lap(0.1);
  phase.on_lap(10.0);  // the link stalled for ten seconds
  EXPECT_EQ(phase.period_s(), 0.0);
  EXPECT_EQ(phase.at(10.05), 0.0f);
  phase.on_lap(10.1);
  EXPECT_NEAR(phase.period_s(), 0.1, 1e-9);
  phase.reset();
  EXPECT_EQ(phase.period_s(), 0.0);
  EXPECT_EQ(phase.at(10.15), 0.0f);
}

TEST(FramePacing, AnimatingWaitsForTheNextRefreshAndIdleBarelyWakes) {
  EXPECT_NEAR(frame_wait_s({.animating = true, .streaming = true}, 0.004, 60.0), 1.0 / 60.0 - 0.004, 1e-12);
  EXPECT_NEAR(frame_wait_s({.animating = true}, 0.0, 144.0), 1.0 / 144.0, 1e-12);
  EXPECT_EQ(frame_wait_s({.animating = true}, 0.03, 60.0), 0.0) << "a slow frame: draw the next at once";
  EXPECT_NEAR(frame_wait_s({.animating = true}, 0.0, 0.0), 1.0 / 60.0, 1e-12) << "no refresh rate known";
  EXPECT_NEAR(frame_wait_s({.animating = true}, 0.0, 1e6), 1.0 / 60.0, 1e-12) << "an absurd one";
  EXPECT_EQ(frame_wait_s({.streaming = true}, 0.0, 60.0), 0.25);
  EXPECT_EQ(frame_wait_s({}, 0.0, 60.0), 1.0);
  EXPECT_EQ(frame_wait_s({.screenshot = true}, 0.0, 60.0), 0.02);
}

TEST(FramePacing, SoftwareRenderersAnimateAtThirtyAndHardwareAtTheMonitorsRate) {
  EXPECT_EQ(animation_hz(60.0, "llvmpipe (LLVM 15.0.6, 256 bits)"), kSoftwareRendererHz);
  EXPECT_EQ(animation_hz(144.0, "Mesa Intel(R) UHD Graphics 620 (KBL GT2)"), 144.0);
  EXPECT_EQ(animation_hz(24.0, "softpipe"), 24.0) << "never faster than the monitor";
  EXPECT_EQ(animation_hz(0.0, nullptr), 60.0) << "nothing known";
}

// A history of `laps` laps, one point each at 1 m, straight ahead.
LapHistory history_of(std::size_t depth, std::size_t laps) {
  LapHistory history(depth);
  for (std::size_t i = 0; i < laps; ++i) {
    Lap lap;
    lap.index = i;
    lap.points = {LapPoint{0.0f, 1000.0f, PointFlag::None}};
    history.push(lap);
  }
  return history;
}

std::vector<std::uint8_t> alphas(const LapHistory& history, float phase, bool fade = true) {
  ColourParams colours;
  colours.fade_old_laps = fade;
  std::vector<std::uint8_t> a;
  for (const PointVertex& v : faded_cloud(history, colours, {}, nullptr, phase).vertices) a.push_back(v.colour.a);
  return a;  // oldest first
}

TEST(PersistenceFade, EveryLapAgesContinuouslyBetweenLaps) {
  const LapHistory history = history_of(10, 5);  // not full: nothing leaves at the next lap
  const auto start = alphas(history, 0.0f);
  const auto half = alphas(history, 0.5f);
  ASSERT_EQ(start.size(), 5u);
  ASSERT_EQ(half.size(), 5u);
  EXPECT_EQ(start.back(), 255);
  for (std::size_t i = 0; i + 1 < 5; ++i) EXPECT_LT(half[i + 1], start[i + 1]) << "lap " << i + 1 << " fades on";
  // Half way, the newest lap stands between where it began and where the next lap puts it.
  EXPECT_LT(half.back(), start.back());
  EXPECT_GT(half.back(), start[3]);
}

TEST(PersistenceFade, TheLapAboutToLeaveAFullHistoryFadesToNothingSoItDoesNotPop) {
  LapHistory history = history_of(4, 4);
  EXPECT_GT(alphas(history, 0.0f).front(), 0) << "the oldest is faint but there";
  EXPECT_EQ(alphas(history, 1.0f).front(), 0) << "gone by the time the next lap pushes it out";
  // Just before the next lap and just after it, every remaining lap looks the same.
  const auto before = alphas(history, 1.0f);
  Lap next;
  next.index = 99;
  next.points = {LapPoint{0.0f, 1000.0f, PointFlag::None}};
  history.push(next);
  const auto after = alphas(history, 0.0f);
  ASSERT_EQ(before.size(), after.size());
  for (std::size_t i = 1; i < before.size(); ++i) EXPECT_NEAR(before[i], after[i - 1], 1) << "lap at age " << 4 - i;
  EXPECT_EQ(after.back(), 255);
}

TEST(PersistenceFade, WithoutFadingOrWithOneLapThePhaseChangesNothing) {
  EXPECT_EQ(alphas(history_of(4, 4), 0.7f, false), alphas(history_of(4, 4), 0.0f, false));
  EXPECT_EQ(alphas(history_of(1, 1), 0.7f), std::vector<std::uint8_t>{255});
}

// The view builds a cloud once a lap and fades it at every frame: faded at one phase after
// another, it must be exactly the cloud built for the last phase, whatever the mode, with a
// dimmed source and the newest lap's ghosts in it.
TEST(PersistenceFade, ACloudFadedAgainIsTheOneBuiltForItsPhase) {
  LapHistory near_side(4), far_side(4);
  for (std::uint64_t i = 0; i < 4; ++i) {
    Lap lap;
    lap.index = i;
    for (int a = 0; a < 90; ++a)
      lap.points.push_back({static_cast<float>(a * 4), 800.0f + 30.0f * static_cast<float>(a),
                            a % 7 == 0 ? PointFlag::Specular : PointFlag::None});
    near_side.push(lap);
    far_side.push(lap);
  }
  SourceLayer layers[2];
  layers[0].history = &near_side;
  layers[1].history = &far_side;
  layers[1].pose.x_m = 1.5;
  layers[1].dim = true;
  InterferenceSettings filter;
  filter.drop_specular = true;  // ghosts in the newest lap
  for (const ColourMode mode : {ColourMode::Range, ColourMode::LapAge, ColourMode::Source}) {
    ColourParams colours;
    colours.mode = mode;
    SourceClouds kept_clouds, fresh_clouds;
    kept_clouds.update(layers, colours, filter, true);
    FadingCloud& kept = kept_clouds.cloud();
    fade_cloud(kept, colours, 0.3f);
    const std::vector<PointVertex> at_start = kept.vertices;
    fade_cloud(kept, colours, 0.8f);
    fresh_clouds.update(layers, colours, filter, true);
    FadingCloud& fresh = fresh_clouds.cloud();
    fade_cloud(fresh, colours, 0.8f);
    ASSERT_EQ(kept.vertices.size(), fresh.vertices.size());
    std::size_t differ = 0, moved_on = 0;
    for (std::size_t i = 0; i < fresh.vertices.size(); ++i) {
      differ += kept.vertices[i].x != fresh.vertices[i].x || kept.vertices[i].y != fresh.vertices[i].y ||
                !(kept.vertices[i].colour == fresh.vertices[i].colour);
      moved_on += !(at_start[i].colour == fresh.vertices[i].colour);
    }
    EXPECT_EQ(differ, 0u) << colour_mode_name(mode);
    EXPECT_GT(moved_on, fresh.vertices.size() / 2) << "the two phases look different, so the test sees the fade";
  }
}

TEST(LapHistory, ItsGenerationChangesWithWhatItHolds) {
  LapHistory history = history_of(4, 2);
  std::uint64_t seen = history.generation();
  const auto changed = [&] {
    const bool did = history.generation() != seen;
    seen = history.generation();
    return did;
  };
  EXPECT_FALSE(changed());
  Lap lap;
  lap.points = {LapPoint{0.0f, 1000.0f, PointFlag::None}};
  history.push(lap);
  EXPECT_TRUE(changed()) << "a lap pushed";
  history.set_depth(2);
  EXPECT_TRUE(changed()) << "the depth set";
  history.clear();
  EXPECT_TRUE(changed()) << "cleared";
  static_cast<void>(history.size());
  EXPECT_FALSE(changed()) << "reading it changes nothing";
}

}  // namespace
}  // namespace ydscope::ui
