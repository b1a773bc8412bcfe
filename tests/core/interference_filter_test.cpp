#include <gtest/gtest.h>

#include "core/protocol/interference_filter.h"

namespace ydscope {
namespace {

std::vector<LapPoint> sample_points() {
  return {{1.0f, 100.0f, PointFlag::None},         {2.0f, 200.0f, PointFlag::Specular},
          {3.0f, 300.0f, PointFlag::AmbientLight}, {4.0f, 400.0f, PointFlag::Reserved},
          {5.0f, 500.0f, PointFlag::Specular},     {6.0f, 600.0f, PointFlag::None}};
}

TEST(InterferenceFilter, RemovesSelectedFlagsAndCountsThem) {
  auto points = sample_points();
  std::vector<LapPoint> ghosts;
  const auto counts = filter_interference(points, {true, false}, &ghosts);
  EXPECT_EQ(counts.specular, 2u);
  EXPECT_EQ(counts.ambient_light, 0u);
  ASSERT_EQ(points.size(), 4u);
  EXPECT_EQ(points[1].angle_deg, 3.0f);  // order kept
  EXPECT_EQ(points[3].angle_deg, 6.0f);
  ASSERT_EQ(ghosts.size(), 2u);
  EXPECT_EQ(ghosts[1].angle_deg, 5.0f);
}

TEST(InterferenceFilter, BothAndNone) {
  Lap lap;
  lap.points = sample_points();
  auto counts = filter_interference(lap, {});
  EXPECT_EQ(counts.total(), 0u);
  EXPECT_EQ(lap.points.size(), 6u);
  counts = filter_interference(lap, {true, true});
  EXPECT_EQ(counts.specular, 2u);
  EXPECT_EQ(counts.ambient_light, 1u);
  EXPECT_EQ(lap.points.size(), 3u);  // flag 1 (reserved) is not interference
}

}  // namespace
}  // namespace ydscope
