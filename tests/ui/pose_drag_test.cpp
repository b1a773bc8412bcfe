// Posing a source by mouse: screen drags through the view's transform into pose changes.
#include <gtest/gtest.h>

#include <cmath>

#include "ui/view/geometry/pose_drag.h"
#include "ui/view/geometry/view_transform.h"

namespace ydscope::ui {
namespace {

ViewTransform view_of(float range_mm) {
  ViewTransform view;
  view.set_viewport({0.0f, 0.0f}, {800.0f, 800.0f});
  view.fit_range(range_mm);
  return view;
}

PoseDrag drag_on(const ViewTransform& view, Vec2 from_px, Vec2 to_px, bool turn) {
  return {view.screen_to_world(from_px), view.screen_to_world(to_px), turn};
}

TEST(PoseDrag, ADragMovesTheCloudAsFarAsThePointerWentInTheWorld) {
  const ViewTransform view = view_of(4000.0f);
  const float px_per_mm = view.px_per_mm();
  Pose pose;
  pose.x_m = 1.0;
  pose.yaw_deg = 30.0;
  // 100 px right and 50 px up on screen (screen y grows downwards): the view draws the common
  // frame's x (forward) up and its y (left) to the left, so that is 50 px forward, 100 px right.
  const Pose moved = dragged_pose(pose, drag_on(view, {400.0f, 400.0f}, {500.0f, 350.0f}, false));
  EXPECT_NEAR(moved.x_m, 1.0 + 50.0 / px_per_mm / 1000.0, 1e-4);
  EXPECT_NEAR(moved.y_m, -100.0 / px_per_mm / 1000.0, 1e-4);
  EXPECT_EQ(moved.yaw_deg, 30.0);  // a move never turns it
}

TEST(PoseDrag, AZoomedInViewMovesItLess) {
  Pose pose;
  const Pose far = dragged_pose(pose, drag_on(view_of(8000.0f), {400, 400}, {480, 400}, false));
  const Pose near = dragged_pose(pose, drag_on(view_of(2000.0f), {400, 400}, {480, 400}, false));
  EXPECT_NEAR(far.y_m, 4.0 * near.y_m, 1e-6);
  EXPECT_LT(near.y_m, 0.0);  // to the right on screen is to the robot's right
}

TEST(PoseDrag, ATurnDragTurnsAboutTheLidarsOwnPosition) {
  Pose pose;
  pose.x_m = 2.0;
  pose.y_m = 1.0;
  pose.yaw_deg = 170.0;
  // The lidar at 2 m forward, 1 m left is drawn at world (-1000, 2000). From straight right of it
  // to straight above it on screen: a quarter turn counter-clockwise.
  const PoseDrag drag{{0.0f, 2000.0f}, {-1000.0f, 3000.0f}, true};
  const Pose turned = dragged_pose(pose, drag);
  EXPECT_NEAR(turned.yaw_deg, -100.0, 1e-4);  // 260 wrapped into [-180, 180)
  EXPECT_EQ(turned.x_m, 2.0);                 // a turn never moves it
  EXPECT_EQ(turned.y_m, 1.0);
  // The point the drag started from, seen by the lidar, now lies where the pointer ended.
  const CommonPoint before = pose.to_common(CommonPoint{1000.0f, 0.0f});
  const CommonPoint after = turned.to_common(CommonPoint{1000.0f, 0.0f});
  const double pi = 3.14159265358979;
  const double swept =
      std::atan2(after.y_mm - 1000.0, after.x_mm - 2000.0) - std::atan2(before.y_mm - 1000.0, before.x_mm - 2000.0);
  EXPECT_NEAR(std::remainder(swept, 2.0 * pi), pi / 2.0, 1e-4);  // the cloud turned with the pointer
}

TEST(PoseDrag, ATurnFromTheLidarsOwnSpotDoesNothing) {
  Pose pose;
  pose.yaw_deg = 12.0;
  EXPECT_EQ(dragged_pose(pose, {{0.0f, 0.0f}, {500.0f, 500.0f}, true}), pose);
}

}  // namespace
}  // namespace ydscope::ui
