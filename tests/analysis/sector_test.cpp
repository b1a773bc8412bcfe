// Sectors: parsing what a user types, wrapping through 0 degrees, and the range band.
#include <gtest/gtest.h>

#include "core/analysis/sector.h"

namespace ydscope {
namespace {

TEST(Sector, ParsesFromToAndMeasuresWidthAndCentre) {
  std::string error;
  const auto s = parse_sector("260:280", error);
  ASSERT_TRUE(s) << error;
  EXPECT_DOUBLE_EQ(s->width_deg(), 20.0);
  EXPECT_DOUBLE_EQ(s->centre_deg(), 270.0);
  EXPECT_TRUE(s->contains_angle(260.0));
  EXPECT_TRUE(s->contains_angle(279.9));
  EXPECT_FALSE(s->contains_angle(280.0));
  EXPECT_FALSE(s->contains_angle(10.0));
}

TEST(Sector, ASectorMayCrossZero) {
  std::string error;
  const auto s = parse_sector("350:10", error);
  ASSERT_TRUE(s) << error;
  EXPECT_DOUBLE_EQ(s->width_deg(), 20.0);
  EXPECT_DOUBLE_EQ(s->centre_deg(), 0.0);
  EXPECT_TRUE(s->contains_angle(355.0));
  EXPECT_TRUE(s->contains_angle(5.0));
  EXPECT_FALSE(s->contains_angle(180.0));
  EXPECT_DOUBLE_EQ(s->offset_deg(2.0), 12.0);
}

TEST(Sector, ARangeBandKeepsTheTargetAndDropsTheWallBehindIt) {
  std::string error;
  Sector s = *parse_sector("260:280", error);
  ASSERT_TRUE(set_range_band(s, "1500:2500", error)) << error;
  EXPECT_EQ(s.name, "260:280 (1500:2500 mm)");
  EXPECT_TRUE(s.contains({270.0f, 2000.0f, PointFlag::None}));
  EXPECT_FALSE(s.contains({270.0f, 3000.0f, PointFlag::None})) << "the wall behind the target";
  EXPECT_FALSE(s.contains({270.0f, 1000.0f, PointFlag::None}));
  EXPECT_TRUE(s.contains({270.0f, 0.0f, PointFlag::None})) << "a miss still counts against the sector";
  for (const char* text : {"", "2000", "a:b", "-1:100", "500:500", "900:100", "1:1e999"}) {
    Sector t = *parse_sector("260:280", error);
    error.clear();
    EXPECT_FALSE(set_range_band(t, text, error)) << text;
    EXPECT_FALSE(error.empty()) << text;
    EXPECT_FALSE(t.min_mm) << text;
  }
}

TEST(Sector, MistakesGetOneSentence) {
  for (const char* text : {"", "260", "a:b", "10:", "400:10", "-5:10", "30:30", "0:360", "1e999:2"}) {
    std::string error;
    EXPECT_FALSE(parse_sector(text, error)) << text;
    EXPECT_FALSE(error.empty()) << text;
    EXPECT_EQ(error.find('\n'), std::string::npos);
  }
}

TEST(Sector, TheRangeBandLeavesOutReturnsBeyondItButKeepsMisses) {
  Sector s;
  s.from_deg = 0;
  s.to_deg = 90;
  s.min_mm = 1000;
  s.max_mm = 2000;
  EXPECT_TRUE(s.contains({45.0f, 1500.0f, PointFlag::None}));
  EXPECT_FALSE(s.contains({45.0f, 2500.0f, PointFlag::None}));
  EXPECT_FALSE(s.contains({45.0f, 500.0f, PointFlag::None}));
  EXPECT_TRUE(s.contains({45.0f, 0.0f, PointFlag::None}));  // no return: a miss inside the region
  EXPECT_FALSE(s.contains({95.0f, 1500.0f, PointFlag::None}));
}

TEST(Sector, InterferenceFlaggedPointsAreNotValidReturns) {
  EXPECT_TRUE(is_valid_return({0.0f, 100.0f, PointFlag::None}));
  EXPECT_FALSE(is_valid_return({0.0f, 0.0f, PointFlag::None}));
  EXPECT_FALSE(is_valid_return({0.0f, 100.0f, PointFlag::Specular}));
  EXPECT_FALSE(is_valid_return({0.0f, 100.0f, PointFlag::AmbientLight}));
}

}  // namespace
}  // namespace ydscope
