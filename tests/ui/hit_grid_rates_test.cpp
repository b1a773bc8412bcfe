#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "ui/view/geometry/grid_layout.h"
#include "ui/view/status/health_names.h"
#include "ui/view/history/health_timeline.h"
#include "ui/view/geometry/hit_test.h"
#include "ui/view/history/rate_meters.h"
#include "ui/view/settings/settings.h"

namespace ydscope::ui {
namespace {

ViewTransform grid_view() {
  ViewTransform v;
  v.set_viewport({0.0f, 0.0f}, {1000.0f, 800.0f});
  v.fit_range(4000.0f);
  return v;
}

TEST(HitTest, FindsTheNearestPointWithinTheRadius) {
  const ViewTransform v = grid_view();
  const std::vector<LapPoint> points{
      {0.0f, 2000.0f, PointFlag::None}, {90.0f, 2000.0f, PointFlag::Specular}, {91.0f, 0.0f, PointFlag::None}};
  const Vec2 right = v.world_to_screen(polar_to_world(90.0f, 2000.0f));
  const auto hit = nearest_point(points, v, right + Vec2{3.0f, 2.0f}, 10.0f);
  ASSERT_TRUE(hit);
  EXPECT_FLOAT_EQ(hit->point.angle_deg, 90.0f);
  EXPECT_EQ(hit->point.flag, PointFlag::Specular);
  EXPECT_NEAR(hit->distance_px, std::hypot(3.0f, 2.0f), 0.05f);
  EXPECT_FALSE(nearest_point(points, v, right + Vec2{30.0f, 0.0f}, 10.0f));
  // The no-return point at the origin is never hit.
  EXPECT_FALSE(nearest_point(points, v, v.world_to_screen({0.0f, 0.0f}), 10.0f));
}

TEST(Ruler, MeasuresBetweenTwoClicksAndRestartsOnTheThird) {
  Ruler ruler;
  EXPECT_FALSE(ruler.length_mm());
  ruler.click({0.0f, 0.0f});
  EXPECT_FALSE(ruler.length_mm());
  ruler.click({300.0f, 400.0f});
  ASSERT_TRUE(ruler.length_mm());
  EXPECT_FLOAT_EQ(*ruler.length_mm(), 500.0f);
  ruler.click({1.0f, 1.0f});
  EXPECT_FALSE(ruler.complete());
  EXPECT_FLOAT_EQ(ruler.first()->x, 1.0f);
}

TEST(GridLayout, RingStepsFollowTheOneTwoFiveLadder) {
  EXPECT_FLOAT_EQ(nice_ring_step_mm(0.1f, 70.0f), 1000.0f);   // 700 mm needed
  EXPECT_FLOAT_EQ(nice_ring_step_mm(0.1f, 110.0f), 2000.0f);  // 1100 mm needed
  EXPECT_FLOAT_EQ(nice_ring_step_mm(1.0f, 60.0f), 100.0f);
  EXPECT_FLOAT_EQ(nice_ring_step_mm(1.0f, 101.0f), 200.0f);
  EXPECT_FLOAT_EQ(nice_ring_step_mm(0.01f, 70.0f), 10000.0f);
  EXPECT_FLOAT_EQ(nice_ring_step_mm(0.1f, 300.0f), 5000.0f);
}

TEST(GridLayout, FormatsDistancesForLabels) {
  EXPECT_EQ(format_distance(50.0f), "50 mm");
  EXPECT_EQ(format_distance(500.0f), "50 cm");
  EXPECT_EQ(format_distance(1000.0f), "1 m");
  EXPECT_EQ(format_distance(2500.0f), "2.5 m");
  EXPECT_EQ(format_distance(20000.0f), "20 m");
}

TEST(GridLayout, RingsCoverTheViewAndLabelsStayInside) {
  const ViewTransform v = grid_view();
  const GridLayout grid = layout_grid(v, 70.0f, 30.0f);
  ASSERT_FALSE(grid.ring_radii_mm.empty());
  EXPECT_GE(grid.ring_step_mm * v.px_per_mm(), 70.0f);
  EXPECT_LE(grid.ring_radii_mm.back(), v.visible_radius_mm());
  EXPECT_GT(grid.ring_radii_mm.back() + grid.ring_step_mm, v.visible_radius_mm());
  for (const GridLabel& label : grid.ring_labels) EXPECT_TRUE(v.contains_screen(label.screen)) << label.text;
  ASSERT_EQ(grid.spoke_angles_deg.size(), 12u);
  ASSERT_EQ(grid.spoke_labels.size(), 12u);  // the lidar is on screen: every spoke leaves it
  EXPECT_EQ(grid.spoke_labels[0].text, "0\xC2\xB0");
  // The unit's 0 deg points back (down, as the laser frame's -x is drawn): its label sits at the
  // bottom margin, horizontally at the lidar; 90 deg is to the left, 180 straight up.
  EXPECT_NEAR(grid.spoke_labels[0].screen.x, 500.0f, 0.5f);
  EXPECT_NEAR(grid.spoke_labels[0].screen.y, 800.0f - 18.0f, 0.5f);
  EXPECT_NEAR(grid.spoke_labels[3].screen.x, 18.0f, 0.5f);
  EXPECT_NEAR(grid.spoke_labels[6].screen.y, 18.0f, 0.5f);
}

TEST(GridLayout, RingLabelsKeepClearOfTheWindowEdgesAtEveryZoom) {
  ViewTransform v = grid_view();
  std::size_t labels = 0;
  for (int step = 0; step < 60; ++step) {
    v.zoom_about(v.viewport_centre(), 1.07f);
    const GridLayout grid = layout_grid(v, 70.0f, 30.0f, 225.0f, 18.0f);
    for (const GridLabel& label : grid.ring_labels) {
      ++labels;
      EXPECT_GE(label.screen.y, 18.0f) << label.text << " at zoom step " << step;
      EXPECT_LE(label.screen.x, 1000.0f - 18.0f - 48.0f) << label.text << " at zoom step " << step;
    }
  }
  EXPECT_GT(labels, 60u);  // the rings still carry labels
}

TEST(GridLayout, SpokesOfALidarOffScreenMayHaveNoLabel) {
  ViewTransform v = grid_view();
  v.pan_by_pixels({-3000.0f, 0.0f});  // the lidar is far to the left of the window
  const GridLayout grid = layout_grid(v, 70.0f, 30.0f);
  EXPECT_LT(grid.spoke_labels.size(), 12u);
  EXPECT_GE(grid.spoke_labels.size(), 1u);
}

TEST(GridLayout, RobustRangeIgnoresFarOutliersAndNoReturns) {
  std::vector<LapPoint> points;
  for (int i = 0; i < 99; ++i) points.push_back({static_cast<float>(i), 3000.0f, PointFlag::None});
  points.push_back({99.0f, 40000.0f, PointFlag::None});
  points.push_back({100.0f, 0.0f, PointFlag::None});
  EXPECT_FLOAT_EQ(robust_max_range_mm(points, 0.98f), 3100.0f);
  EXPECT_FLOAT_EQ(robust_max_range_mm(points, 1.0f), 40100.0f);
  EXPECT_FLOAT_EQ(robust_max_range_mm({}, 0.98f), 0.0f);
}

TEST(ScanRateMeter, MeasuresLapsPerSecondAndRestartsAfterAGap) {
  ScanRateMeter meter;
  std::int64_t t = 1'000'000'000;
  std::uint64_t lap = 0;
  meter.add_lap_end(lap, t);
  EXPECT_FALSE(meter.hz());
  for (int i = 0; i < 40; ++i) meter.add_lap_end(++lap, t += 100'000'000);  // 10 Hz
  ASSERT_TRUE(meter.hz());
  EXPECT_NEAR(*meter.hz(), 10.0, 1e-9);
  meter.add_lap_end(++lap, t += 5'000'000'000);  // a 5 s stall
  EXPECT_FALSE(meter.hz());
  for (int i = 0; i < 5; ++i) meter.add_lap_end(++lap, t += 80'000'000);  // 12.5 Hz
  EXPECT_NEAR(*meter.hz(), 12.5, 1e-9);
}

TEST(ScanRateMeter, SkippedLapsStillCount) {
  ScanRateMeter meter;
  std::int64_t t = 0;
  // The UI shows every other lap of a 10 Hz stream: the device still turns at 10 Hz.
  for (std::uint64_t lap = 0; lap < 20; lap += 2) meter.add_lap_end(lap, t += 200'000'000);
  ASSERT_TRUE(meter.hz());
  EXPECT_NEAR(*meter.hz(), 10.0, 1e-9);
  meter.add_lap_end(0, t += 100'000'000);  // a new stream starts its indices again
  EXPECT_FALSE(meter.hz());
}

TEST(CounterRate, PerSecondFromAGrowingCounter) {
  CounterRate rate(1.0);
  rate.sample(0.0, 1000);
  rate.sample(0.5, 1500);
  EXPECT_DOUBLE_EQ(rate.per_second(), 0.0);  // not a full period yet
  rate.sample(1.0, 3000);
  EXPECT_DOUBLE_EQ(rate.per_second(), 2000.0);
  rate.sample(1.5, 10);  // counter reset (a new connection)
  EXPECT_DOUBLE_EQ(rate.per_second(), 0.0);
}

TEST(RunningMean, AveragesTheLastValues) {
  RunningMean mean;
  for (int i = 0; i < 100; ++i) mean.add(i < 40 ? 100.0 : 2.0);
  EXPECT_DOUBLE_EQ(mean.mean(), 2.0);
  EXPECT_DOUBLE_EQ(mean.max(), 2.0);
}

TEST(HealthNames, G1BitsHaveNamesAndG6StatusHasMeanings) {
  ASSERT_EQ(health_bits(Model::G1).size(), 6u);
  EXPECT_EQ(health_bits(Model::G1)[1].name, "Encode");
  EXPECT_TRUE(health_bits(Model::G6).empty());
  EXPECT_EQ(describe_health_bits(Model::G1, 0), "all normal");
  EXPECT_EQ(describe_health_bits(Model::G1, 0x21), "Sensor, Data");
  EXPECT_FALSE(health_status_info(0).is_problem);
  EXPECT_EQ(health_status_info(2).name, "error");
  EXPECT_TRUE(health_status_info(7).is_problem);
}

TEST(HealthTimeline, RecordsOnlyChanges) {
  HealthTimeline timeline;
  EXPECT_TRUE(timeline.observe("CT health", 0, 1.0, "all normal"));
  EXPECT_FALSE(timeline.observe("CT health", 0, 2.0, "all normal"));
  EXPECT_TRUE(timeline.observe("A5 92", 0, 2.0, "all normal"));
  EXPECT_TRUE(timeline.observe("CT health", 2, 3.0, "Encode"));
  ASSERT_EQ(timeline.events().size(), 3u);
  EXPECT_EQ(timeline.events().back().text, "Encode");
  EXPECT_DOUBLE_EQ(timeline.events().back().time_s, 3.0);
  for (int i = 0; i < 500; ++i) timeline.observe("CT health", static_cast<std::uint32_t>(i % 2), 4.0 + i, "x");
  EXPECT_EQ(timeline.events().size(), HealthTimeline::kMaxEvents);
}

TEST(Settings, RoundTripAndToleranceOfBadLines) {
  ViewSettings s;
  s.colours.mode = ColourMode::LapAge;
  s.colours.palette = Palette::Viridis;
  s.colours.far_mm = 12000.0f;
  s.point_size_px = 5.0f;
  s.persistence_laps = 7;
  s.interference.drop_ambient = true;
  s.show_panels = false;
  s.last_replay_file = "/tmp/demo.ydrec";
  EXPECT_EQ(parse_settings(format_settings(s)), s);
  std::vector<std::string> notes;
  const ViewSettings odd =
      parse_settings("nonsense\npersistence_laps = 999\npoint_size_px = abc\nfuture_key = 1\n", &notes);
  EXPECT_EQ(odd.persistence_laps, ViewSettings{}.persistence_laps);
  EXPECT_FLOAT_EQ(odd.point_size_px, ViewSettings{}.point_size_px);
  ASSERT_EQ(notes.size(), 2u);
  EXPECT_EQ(notes[0], "persistence_laps = 999 is not a whole number from 1 to 60; using the default, 10");
  EXPECT_EQ(notes[1], "point_size_px = abc is not a number from 1 to 20; using the default, 3");
}

// Issue 17: 3e38 laps was a float-to-int conversion out of range (undefined behaviour).
TEST(Settings, EveryNumericValueOutOfRangeFallsBackToItsDefaultWithANote) {
  std::vector<std::string> notes;
  const ViewSettings s = parse_settings(
      "persistence_laps = 3e38\npersistence_laps = -5\npersistence_laps = 2.5\npoint_size_px = 1e30\n"
      "point_size_px = 0.5\nnear_mm = -1\nnear_mm = inf\nfar_mm = 1e39\nfar_mm = nan\nfar_mm = 0\n",
      &notes);
  EXPECT_EQ(s, ViewSettings{});
  EXPECT_EQ(notes.size(), 10u);
  for (const auto& note : notes) EXPECT_NE(note.find("using the default"), std::string::npos) << note;
  // In range is taken as written, without a note.
  notes.clear();
  const ViewSettings edge =
      parse_settings("persistence_laps = 60\npoint_size_px = 1\nnear_mm = 0\nfar_mm = 100000\n", &notes);
  EXPECT_TRUE(notes.empty());
  EXPECT_EQ(edge.persistence_laps, 60);
  EXPECT_FLOAT_EQ(edge.point_size_px, 1.0f);
  EXPECT_FLOAT_EQ(edge.colours.far_mm, 100000.0f);
}

}  // namespace
}  // namespace ydscope::ui

#include "ui/view/geometry/grid_geometry.h"

namespace ydscope::ui {
namespace {

TEST(GridGeometry, RingsAreQuadsAroundTheCircleAndSpokesLeaveTheMarkerClear) {
  const ViewTransform v = grid_view();
  const GridLayout grid = layout_grid(v, 70.0f, 30.0f);
  GridStyle style;
  std::vector<LineVertex> lines;
  build_grid_geometry(v, grid, style, lines);
  ASSERT_EQ(lines.size() % 6, 0u);  // two triangles per segment
  const float half_px = line_quad_half_px(style);
  const float half_mm = half_px / v.px_per_mm();
  const float first_ring = grid.ring_radii_mm.front();
  // The first ring's vertices lie half a quad either side of its radius.
  for (std::size_t i = 0; i < 12; ++i) {
    const float r = length({lines[i].x, lines[i].y});
    EXPECT_NEAR(std::fabs(r - first_ring), half_mm, half_mm * 0.05f);
    EXPECT_FLOAT_EQ(std::fabs(lines[i].edge_px), half_px);
  }
  // The last 12 segments are the spokes: they start style.spoke_start_px from the lidar.
  const std::size_t spokes = grid.spoke_angles_deg.size() * 6;
  ASSERT_GT(lines.size(), spokes);
  const LineVertex& spoke_start = lines[lines.size() - spokes];
  EXPECT_NEAR(length({spoke_start.x, spoke_start.y}) * v.px_per_mm(), style.spoke_start_px, half_px + 0.01f);
}

}  // namespace
}  // namespace ydscope::ui
