// "This wall is straight ahead": the yaw a click sets puts the clicked point on the robot's +x
// axis as seen from the lidar, wherever the lidar sits and however it is mounted.
#include "ui/view/geometry/forward_click.h"

#include <gtest/gtest.h>

#include <cmath>

namespace ydscope::ui {
namespace {

TEST(ForwardClick, TheClickedPointEndsStraightAheadOfTheLidar) {
  const Pose poses[] = {{}, {1.0, -0.5, 30, false}, {-2.0, 3.0, -150, true}, {0.3, 0.2, 90, false, 12}};
  for (const Pose& pose : poses) {
    for (const float angle : {0.0f, 45.0f, 100.0f, 270.0f}) {
      SCOPED_TRACE(format_pose(pose) + " at " + std::to_string(angle));
      // A wall point the lidar saw at this device angle, 2.5 m out.
      const CommonPoint seen = laser_point({angle, 2500.0f, PointFlag::None});
      const auto turned = facing_forward(pose, seen);
      ASSERT_TRUE(turned);
      EXPECT_EQ(turned->x_m, pose.x_m);  // it turns about its own position
      EXPECT_EQ(turned->y_m, pose.y_m);
      EXPECT_EQ(turned->upside_down, pose.upside_down);
      EXPECT_EQ(turned->angle_offset_deg, pose.angle_offset_deg);
      EXPECT_GT(turned->yaw_deg, -180.0);
      EXPECT_LE(turned->yaw_deg, 180.0);
      const CommonPoint now = turned->to_common(seen);
      // Straight ahead of the lidar: along +x from its position, 2.5 m out.
      EXPECT_NEAR(now.x_mm - pose.x_m * 1000.0, 2500.0, 1.0);
      EXPECT_NEAR(now.y_mm - pose.y_m * 1000.0, 0.0, 1.0);
    }
  }
}

TEST(ForwardClick, TheUnitsOwnAheadGivesYawZeroAndAClickOnTheLidarNothing) {
  // The laser frame's forward is the unit's 180 degrees: clicking there leaves the yaw at 0.
  const auto same = facing_forward({}, laser_point({180.0f, 1000.0f, PointFlag::None}));
  ASSERT_TRUE(same);
  EXPECT_EQ(same->yaw_deg, 0.0);
  EXPECT_FALSE(std::signbit(same->yaw_deg));
  // The unit's 90 (its left) straight ahead: turned a quarter clockwise.
  EXPECT_EQ(facing_forward({}, laser_point({90.0f, 1000.0f, PointFlag::None}))->yaw_deg, -90.0);
  EXPECT_FALSE(facing_forward({1, 1, 45, false}, {0.2f, -0.3f}));
}

}  // namespace
}  // namespace ydscope::ui
