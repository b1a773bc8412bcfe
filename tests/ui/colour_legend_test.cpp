// The booth view's legend says what the colours mean in the mode in use, with the cloud's own
// colours: metres under a range bar, newest to oldest for lap age, the flags by name.
#include "ui/view/scene/colour_legend.h"

#include <gtest/gtest.h>

namespace ydscope::ui {
namespace {

TEST(ColourLegend, RangeBarWithTicksInMetresAcrossTheFittedRange) {
  ColourParams colours;
  colours.near_mm = 0.0f;
  colours.far_mm = 8800.0f;  // what auto-range fitted
  const ColourLegend legend = describe_legend(colours, 10);
  EXPECT_EQ(legend.title, "range");
  ASSERT_GE(legend.bar.size(), 16u);
  EXPECT_EQ(legend.bar.front(), sample_palette(colours.palette, 0.0f));
  EXPECT_EQ(legend.bar.back(), sample_palette(colours.palette, 1.0f));
  ASSERT_GE(legend.ticks.size(), 3u);
  ASSERT_LE(legend.ticks.size(), 6u);
  EXPECT_EQ(legend.ticks.front().text, "0 m");
  EXPECT_FLOAT_EQ(legend.ticks.front().at, 0.0f);
  EXPECT_EQ(legend.ticks[1].text, "2 m");
  EXPECT_NEAR(legend.ticks[1].at, 2000.0f / 8800.0f, 1e-5f);
  for (const LegendTick& t : legend.ticks) {
    EXPECT_GE(t.at, 0.0f);
    EXPECT_LE(t.at, 1.0f);
  }
  EXPECT_TRUE(legend.swatches.empty());
}

TEST(ColourLegend, AManualRangeStartsItsTicksAtNear) {
  ColourParams colours;
  colours.near_mm = 1500.0f;
  colours.far_mm = 3000.0f;
  const ColourLegend legend = describe_legend(colours, 10);
  ASSERT_FALSE(legend.ticks.empty());
  EXPECT_GE(legend.ticks.front().at, 0.0f);
  EXPECT_EQ(legend.ticks.front().text, "1.5 m");
}

TEST(ColourLegend, LapAgeRunsFromTheNewestToThePersistencesOldest) {
  ColourParams colours;
  colours.mode = ColourMode::LapAge;
  const ColourLegend legend = describe_legend(colours, 30);
  EXPECT_EQ(legend.title, "lap age");
  ASSERT_EQ(legend.ticks.size(), 2u);
  EXPECT_EQ(legend.ticks[0].text, "newest");
  EXPECT_EQ(legend.ticks[1].text, "29 laps ago");
  EXPECT_EQ(legend.bar.front().a, 255) << "shown at full strength, not faded";
  EXPECT_EQ(legend.bar.back().a, 255);
}

TEST(ColourLegend, FlagModeNamesTheFlags) {
  ColourParams colours;
  colours.mode = ColourMode::Flag;
  const ColourLegend legend = describe_legend(colours, 10);
  EXPECT_TRUE(legend.bar.empty());
  ASSERT_EQ(legend.swatches.size(), 3u);
  EXPECT_EQ(legend.swatches[1].text, "specular (2)");
  EXPECT_EQ(legend.swatches[1].colour, flag_colour(PointFlag::Specular));
  EXPECT_EQ(legend.swatches[2].text, "ambient light (3)");
}

TEST(ColourLegend, BoothTypeGrowsWithTheScreen) {
  EXPECT_GT(booth_text_px(1080.0f), 40.0f) << "legible across a stand";
  EXPECT_GT(booth_text_px(2160.0f), booth_text_px(1080.0f));
  EXPECT_GE(booth_text_px(480.0f), 24.0f);
}

}  // namespace
}  // namespace ydscope::ui
