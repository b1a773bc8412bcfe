#include <gtest/gtest.h>

#include "ui/view/scene/colour_map.h"
#include "ui/view/scene/lap_history.h"
#include "tests/ui/faded_cloud.h"
#include "ui/view/scene/point_cloud.h"

namespace ydscope::ui {
namespace {

Lap make_lap(std::uint64_t index, std::initializer_list<LapPoint> points) {
  Lap lap;
  lap.index = index;
  lap.points.assign(points);
  lap.last_rx_ns = static_cast<std::int64_t>(index) * 100'000'000;
  return lap;
}

TEST(ColourMap, PaletteEndsDifferAndInterpolateBetweenStops) {
  const Rgba8 a = sample_palette(Palette::Viridis, 0.0f);
  const Rgba8 b = sample_palette(Palette::Viridis, 1.0f);
  EXPECT_NE(a, b);
  EXPECT_LT(a.g, b.g);  // viridis goes from purple to yellow
  EXPECT_EQ(sample_palette(Palette::Turbo, -3.0f), sample_palette(Palette::Turbo, 0.0f));
  EXPECT_EQ(sample_palette(Palette::Turbo, 7.0f), sample_palette(Palette::Turbo, 1.0f));
  const Rgba8 mid = sample_palette(Palette::Viridis, 0.0625f);  // half way between stop 0 and 1
  EXPECT_GT(mid.g, a.g);
}

TEST(ColourMap, RangeModeMapsNearAndFarToThePaletteEnds) {
  ColourParams params;
  params.near_mm = 1000.0f;
  params.far_mm = 3000.0f;
  params.fade_old_laps = false;
  const LapPoint near{0.0f, 500.0f, PointFlag::None};
  const LapPoint far{0.0f, 9000.0f, PointFlag::None};
  EXPECT_EQ(point_colour(params, near, 0.0f), sample_palette(params.palette, 0.0f));
  EXPECT_EQ(point_colour(params, far, 0.0f), sample_palette(params.palette, 1.0f));
}

TEST(ColourMap, FlagModeAndFading) {
  ColourParams params;
  params.mode = ColourMode::Flag;
  const LapPoint spec{10.0f, 500.0f, PointFlag::Specular};
  const LapPoint amb{10.0f, 500.0f, PointFlag::AmbientLight};
  const Rgba8 s = point_colour(params, spec, 0.0f);
  EXPECT_NE(s, point_colour(params, amb, 0.0f));
  EXPECT_EQ(s.a, 255);
  EXPECT_LT(point_colour(params, spec, 1.0f).a, 60);
  EXPECT_LT(ghost_colour(PointFlag::Specular).a, 100);
}

TEST(LapHistory, KeepsTheNewestLapsUpToItsDepth) {
  LapHistory history(3);
  for (std::uint64_t i = 0; i < 5; ++i) history.push(make_lap(i, {{1.0f, 100.0f, PointFlag::None}}));
  ASSERT_EQ(history.size(), 3u);
  EXPECT_EQ(history.newest().index, 4u);
  EXPECT_EQ(history.at_age(2).index, 2u);
  EXPECT_THROW((void)history.at_age(3), std::out_of_range);
  history.set_depth(1);
  EXPECT_EQ(history.size(), 1u);
  EXPECT_EQ(history.newest().index, 4u);
  history.set_depth(10);
  history.push(make_lap(5, {}));
  EXPECT_EQ(history.size(), 2u);
  EXPECT_EQ(history.at_age(1).index, 4u);
}

TEST(PointCloud, FiltersInterferenceCountsRemovedAndDrawsGhosts) {
  LapHistory history(2);
  history.push(make_lap(0, {{0.0f, 1000.0f, PointFlag::Specular}, {5.0f, 1000.0f, PointFlag::None}}));
  history.push(make_lap(1, {{0.0f, 1000.0f, PointFlag::Specular},
                            {1.0f, 1000.0f, PointFlag::AmbientLight},
                            {2.0f, 1000.0f, PointFlag::AmbientLight},
                            {3.0f, 0.0f, PointFlag::None},
                            {4.0f, 1000.0f, PointFlag::None}}));
  ColourParams colours;
  InterferenceSettings filter;
  const auto [all, every] = faded_cloud(history, colours, filter);
  EXPECT_EQ(all.drawn, 6u);  // everything but the no-return point
  EXPECT_EQ(every.size(), 6u);
  EXPECT_EQ(all.newest_no_return, 1u);

  filter.drop_specular = true;
  filter.drop_ambient = true;
  filter.show_ghosts = true;
  const auto [filtered, out] = faded_cloud(history, colours, filter);
  EXPECT_EQ(filtered.newest_specular_removed, 1u);
  EXPECT_EQ(filtered.newest_ambient_removed, 2u);
  EXPECT_EQ(filtered.drawn, 2u);   // one clean point per lap
  EXPECT_EQ(filtered.ghosts, 3u);  // only the newest lap's removed points
  // The newest lap is drawn last: its clean point is the final vertex and fully opaque.
  EXPECT_EQ(out.back().colour.a, 255);
  // (the unit's 0 points down the view: polar_to_world)
  EXPECT_NEAR(out.back().y, -1000.0f * std::cos(4.0f * 3.14159265f / 180.0f), 0.01f);

  filter.show_ghosts = false;
  const FadedCloud without = faded_cloud(history, colours, filter);
  EXPECT_EQ(without.stats.ghosts, 0u);
  EXPECT_EQ(without.vertices.size(), 2u);
}

}  // namespace
}  // namespace ydscope::ui
