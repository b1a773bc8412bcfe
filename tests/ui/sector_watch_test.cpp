// The Sectors panel's numbers: each lap's statistics of the points in a watched sector, its mean
// over the laps, a new session starting empty, and the sectors remembered in settings.ini.
#include <gtest/gtest.h>

#include "ui/view/history/sector_watch.h"
#include "ui/view/settings/settings.h"

namespace ydscope::ui {
namespace {

// A wall 2000 mm away from 260 to 280 degrees (one point per degree), nothing elsewhere.
Lap wall_lap(float range_mm, int misses = 0) {
  Lap lap;
  for (int a = 0; a < 360; ++a) {
    const bool on_wall = a >= 260 && a < 280;
    lap.points.push_back({static_cast<float>(a), on_wall && a - 260 >= misses ? range_mm : 0.0f, PointFlag::None});
  }
  return lap;
}

Sector sector(const char* spec) {
  std::string error;
  const auto s = parse_sector_spec(spec, error);
  EXPECT_TRUE(s) << error;
  return s.value_or(Sector{});
}

TEST(SectorWatch, EachLapReplacesTheStatisticsAndAddsItsMean) {
  SectorWatch w(sector("260:280"));
  EXPECT_FALSE(w.newest());
  w.add_lap(wall_lap(2000.0f));
  ASSERT_TRUE(w.newest());
  EXPECT_EQ(w.newest()->points, 20u);
  EXPECT_DOUBLE_EQ(w.newest()->valid_share, 1.0);
  EXPECT_DOUBLE_EQ(w.newest()->range_mm.mean, 2000.0);
  w.add_lap(wall_lap(2100.0f, 5));  // 5 of the 20 points without a return
  EXPECT_EQ(w.newest()->points, 20u) << "the statistics are the newest lap's, not a sum";
  EXPECT_DOUBLE_EQ(w.newest()->valid_share, 0.75);
  ASSERT_EQ(w.mean_mm().size(), 2u);
  EXPECT_FLOAT_EQ(*w.mean_mm().last(), 2100.0f);
  EXPECT_FALSE(w.histogram().empty());
  EXPECT_EQ(w.valid_pct_by_angle().size(), SectorStatisticsOptions{}.angle_bins);
  EXPECT_FLOAT_EQ(w.valid_pct_by_angle().front(), 0.0f) << "the first degrees are the misses";
  EXPECT_FLOAT_EQ(w.valid_pct_by_angle().back(), 100.0f);
  w.clear();
  EXPECT_FALSE(w.newest());
  EXPECT_EQ(w.mean_mm().size(), 0u);
}

TEST(SectorWatch, ARangeBandLeavesOutTheWallBehindTheTarget) {
  SectorWatch w(sector("260:280 1000:1500"));
  w.add_lap(wall_lap(2000.0f));
  EXPECT_EQ(w.newest()->points, 0u);
  EXPECT_EQ(w.spec(), "260:280 1000:1500");
}

TEST(SectorWatchList, ASectorIsWatchedOnceAndAtMostEightAtATime) {
  std::vector<SectorWatch> sectors;
  EXPECT_EQ(watch_sector(sectors, "260:280"), "");
  EXPECT_EQ(watch_sector(sectors, "260:280"), "sector 260:280 is watched already");
  EXPECT_NE(watch_sector(sectors, "260"), "");  // a mistake: its sentence comes from the parser
  ASSERT_EQ(sectors.size(), 1u);
  for (int from = 0; sectors.size() < kMaxWatchedSectors; from += 20)
    EXPECT_EQ(watch_sector(sectors, std::to_string(from) + ":" + std::to_string(from + 10)), "");
  EXPECT_EQ(watch_sector(sectors, "300:310"), "at most 8 sectors; remove one first");
  EXPECT_EQ(sectors.size(), kMaxWatchedSectors);
  EXPECT_EQ(sectors.front().spec(), "260:280");
}

TEST(SectorSettings, SectorsAreRememberedAndBadLinesSaySo) {
  ViewSettings s;
  s.sectors = {"260:280", "350:10 500:2500"};
  EXPECT_EQ(parse_settings(format_settings(s)), s);
  std::vector<std::string> notes;
  std::string text;
  for (int i = 0; i < 10; ++i) text += "sector = " + std::to_string(i * 10) + ":" + std::to_string(i * 10 + 5) + "\n";
  text += "sector = 10\nsector = 10:20 9:1\n";
  const ViewSettings many = parse_settings(text, &notes);
  EXPECT_EQ(many.sectors.size(), kMaxWatchedSectors);
  ASSERT_EQ(notes.size(), 4u);
  EXPECT_EQ(notes[0], "sector = 80:85 is left out: at most 8 sectors");
  for (const auto& note : notes) EXPECT_NE(note.find("is left out"), std::string::npos) << note;
}

}  // namespace
}  // namespace ydscope::ui
