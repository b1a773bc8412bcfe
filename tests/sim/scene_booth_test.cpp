// The booth scene: a stand whose walls stay put and an aisle where visitors walk past at walking
// pace, so motion highlighting has something to find with no hardware attached.
#include "core/sim/scene.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>

namespace ydscope {
namespace {

constexpr std::int64_t kSecond = 1'000'000'000;

TEST(BoothScene, IsListedAndDeterministic) {
  EXPECT_NE(std::string(scene_names()).find("booth"), std::string::npos);
  const auto a = make_scene("booth", 3);
  const auto b = make_scene("booth", 3);
  ASSERT_TRUE(a && b);
  for (int i = 0; i < 360; i += 7)
    EXPECT_EQ(a->sample(i, 5 * kSecond).range_mm, b->sample(i, 5 * kSecond).range_mm) << i << " deg";
}

TEST(BoothScene, EveryDirectionReturnsSomething) {
  const auto scene = make_scene("booth", 3);
  int none = 0;
  for (int i = 0; i < 3600; ++i) none += scene->sample(i * 0.1, 2 * kSecond).range_mm == 0.0;
  EXPECT_EQ(none, 0) << "the hall is closed: walls, end walls and the opposite stands";
}

TEST(BoothScene, TheBackWallStaysAndTheAisleHasVisitorsWalkingPast) {
  const auto scene = make_scene("booth", 3);
  // Straight behind the lidar: the stand's back wall, 1.5 m, whatever the time.
  for (std::int64_t s = 0; s < 30; s += 3) EXPECT_NEAR(scene->sample(180.0, s * kSecond).range_mm, 1500.0, 40.0);
  // Across the aisle (the opposite stands are 3.3 m ahead): over 30 s, visitors block the view
  // a fair share of the time, closer than the opposite wall, and never for long at one spot.
  int blocked = 0, samples = 0;
  for (std::int64_t ms = 0; ms < 30'000; ms += 100) {
    for (const double angle : {-30.0, -10.0, 0.0, 10.0, 30.0}) {
      const double wall = 3300.0 / std::cos(angle * 3.14159265358979 / 180.0);
      blocked += scene->sample(angle < 0 ? angle + 360.0 : angle, ms * 1'000'000).range_mm < wall - 300.0;
      ++samples;
    }
  }
  EXPECT_GT(blocked, samples / 50) << "nobody walks past";
  EXPECT_LT(blocked, samples / 2) << "the aisle is a crowd, not passers-by";
}

}  // namespace
}  // namespace ydscope
