// Motion highlighting learns the static room per angle bin and flags the returns closer than it:
// a person walking in front of a wall is moving, the wall is not, and neither is lap noise.
#include "ui/view/scene/motion_background.h"

#include <gtest/gtest.h>

#include <cmath>

namespace ydscope::ui {
namespace {

// A round room of `radius_mm` with a little noise, and optionally a person (a 10 degree wide
// blob at 1.5 m) at `person_deg`.
Lap room_lap(std::uint64_t index, float radius_mm, float person_deg = -1.0f) {
  Lap lap;
  lap.index = index;
  for (int i = 0; i < 1440; ++i) {
    const float angle = static_cast<float>(i) * 0.25f;
    float range = radius_mm + 20.0f * std::sin(static_cast<float>(i * 7 + static_cast<int>(index) * 13));
    if (person_deg >= 0.0f && std::fabs(angle - person_deg) < 5.0f) range = 1500.0f;
    lap.points.push_back({angle, range, PointFlag::None});
  }
  return lap;
}

TEST(MotionBackground, NothingMovesBeforeTheRoomIsLearned) {
  MotionBackground background;
  background.add_lap(room_lap(0, 4000.0f, 90.0f));
  EXPECT_FALSE(background.is_moving({90.0f, 1500.0f, PointFlag::None}));
}

TEST(MotionBackground, APersonWalkingPastIsMovingTheWallIsNot) {
  MotionBackground background;
  // Forty laps; the person walks from 30 to 150 degrees, 3 degrees a lap.
  for (std::uint64_t i = 0; i < MotionBackground::kLaps; ++i)
    background.add_lap(room_lap(i, 4000.0f, 30.0f + 3.0f * static_cast<float>(i)));
  EXPECT_NEAR(background.background_mm(100.0f), 4000.0f, 60.0f) << "the room behind the path";
  const Lap now = room_lap(99, 4000.0f, 120.0f);
  int moving_person = 0, moving_wall = 0, person = 0, wall = 0;
  for (const LapPoint& p : now.points) {
    const bool on_person = std::fabs(p.angle_deg - 120.0f) < 5.0f;
    (on_person ? person : wall) += 1;
    if (background.is_moving(p)) (on_person ? moving_person : moving_wall) += 1;
  }
  EXPECT_EQ(moving_person, person) << "every return of the person is closer than the room";
  EXPECT_EQ(moving_wall, 0) << "wall noise of 20 mm is not motion";
}

TEST(MotionBackground, SomeoneWhoStaysBecomesBackground) {
  MotionBackground background;
  for (std::uint64_t i = 0; i < MotionBackground::kLaps; ++i) background.add_lap(room_lap(i, 4000.0f, 200.0f));
  EXPECT_NEAR(background.background_mm(200.0f), 1500.0f, 1.0f);
  EXPECT_FALSE(background.is_moving({200.0f, 1500.0f, PointFlag::None}));
}

TEST(MotionBackground, AnglesWrapAndClearForgets) {
  MotionBackground background;
  for (std::uint64_t i = 0; i < MotionBackground::kLaps; ++i) background.add_lap(room_lap(i, 3000.0f));
  EXPECT_NEAR(background.background_mm(-0.1f), background.background_mm(359.9f), 1e-3f);
  EXPECT_TRUE(background.is_moving({359.9f, 1000.0f, PointFlag::None}));
  background.clear();
  EXPECT_FLOAT_EQ(background.background_mm(10.0f), 0.0f);
  EXPECT_FALSE(background.is_moving({10.0f, 1000.0f, PointFlag::None}));
}

}  // namespace
}  // namespace ydscope::ui
