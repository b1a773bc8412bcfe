#include "ui/view/geometry/view_transform.h"

#include <gtest/gtest.h>

namespace ydscope::ui {
namespace {

ViewTransform make_view() {
  ViewTransform v;
  v.set_viewport({100.0f, 50.0f}, {800.0f, 600.0f});
  v.fit_range(5000.0f);
  return v;
}

TEST(ViewTransform, FitRangePutsTheLidarAtTheCentreAndTheRangeInside) {
  const ViewTransform v = make_view();
  const Vec2 origin = v.world_to_screen({0.0f, 0.0f});
  EXPECT_FLOAT_EQ(origin.x, 500.0f);
  EXPECT_FLOAT_EQ(origin.y, 350.0f);
  // 5 m ahead is above the centre, inside the shorter (600 px) side.
  const Vec2 ahead = v.world_to_screen({0.0f, 5000.0f});
  EXPECT_LT(ahead.y, origin.y);
  EXPECT_GT(ahead.y, 50.0f);
  EXPECT_NEAR(origin.y - ahead.y, 300.0f * 0.92f, 0.01f);
}

TEST(ViewTransform, ScreenAndWorldRoundTrip) {
  ViewTransform v = make_view();
  v.pan_by_pixels({37.0f, -12.0f});
  v.zoom_about({300.0f, 200.0f}, 2.5f);
  const Vec2 w{1234.0f, -987.0f};
  const Vec2 back = v.screen_to_world(v.world_to_screen(w));
  EXPECT_NEAR(back.x, w.x, 0.05f);
  EXPECT_NEAR(back.y, w.y, 0.05f);
}

TEST(ViewTransform, ZoomKeepsThePointUnderTheCursorFixed) {
  ViewTransform v = make_view();
  const Vec2 cursor{700.0f, 120.0f};
  const Vec2 before = v.screen_to_world(cursor);
  v.zoom_about(cursor, 1.7f);
  const Vec2 after = v.screen_to_world(cursor);
  EXPECT_NEAR(after.x, before.x, 0.05f);
  EXPECT_NEAR(after.y, before.y, 0.05f);
  EXPECT_GT(v.px_per_mm(), 0.0f);
}

TEST(ViewTransform, ZoomIsClamped) {
  ViewTransform v = make_view();
  for (int i = 0; i < 200; ++i) v.zoom_about({500.0f, 350.0f}, 2.0f);
  EXPECT_FLOAT_EQ(v.px_per_mm(), ViewTransform::kMaxPxPerMm);
  for (int i = 0; i < 400; ++i) v.zoom_about({500.0f, 350.0f}, 0.5f);
  EXPECT_FLOAT_EQ(v.px_per_mm(), ViewTransform::kMinPxPerMm);
}

TEST(ViewTransform, DragMovesTheWorldWithTheMouse) {
  ViewTransform v = make_view();
  const Vec2 grabbed = v.screen_to_world({400.0f, 300.0f});
  v.pan_by_pixels({50.0f, 20.0f});
  const Vec2 now = v.world_to_screen(grabbed);
  EXPECT_NEAR(now.x, 450.0f, 0.01f);
  EXPECT_NEAR(now.y, 320.0f, 0.01f);
}

TEST(ViewTransform, NdcTransformMatchesTheScreenMapping) {
  ViewTransform v = make_view();
  v.pan_by_pixels({-80.0f, 33.0f});
  const NdcTransform ndc = v.ndc_transform();
  const Vec2 w{2000.0f, 1500.0f};
  const Vec2 s = v.world_to_screen(w);
  const float nx = w.x * ndc.scale_x + ndc.offset_x;
  const float ny = w.y * ndc.scale_y + ndc.offset_y;
  // NDC x -1..1 spans the viewport left to right; y -1..1 bottom to top.
  EXPECT_NEAR((nx + 1.0f) * 0.5f * 800.0f + 100.0f, s.x, 0.01f);
  EXPECT_NEAR((1.0f - ny) * 0.5f * 600.0f + 50.0f, s.y, 0.01f);
}

// The laser frame drawn as ROS tools draw it: the unit's 180 (forward) up, 90 (left) to the left,
// its 0 down; the unit's clockwise angles sweep clockwise on screen.
TEST(Polar, TheUnitsAnglesGrowClockwiseFromItsZeroAtTheBottom) {
  const Vec2 zero = polar_to_world(0.0f, 1000.0f);
  const Vec2 left = polar_to_world(90.0f, 1000.0f);
  const Vec2 ahead = polar_to_world(180.0f, 1000.0f);
  EXPECT_NEAR(zero.x, 0.0f, 1e-3f);
  EXPECT_NEAR(zero.y, -1000.0f, 1e-3f);
  EXPECT_NEAR(left.x, -1000.0f, 1e-3f);
  EXPECT_NEAR(left.y, 0.0f, 1e-2f);
  EXPECT_NEAR(ahead.x, 0.0f, 1e-2f);
  EXPECT_NEAR(ahead.y, 1000.0f, 1e-3f);
  EXPECT_NEAR(world_angle_deg(polar_to_world(271.5f, 300.0f)), 271.5f, 1e-3f);
}

TEST(ViewTransform, VisibleRadiusReachesTheFarthestCorner) {
  const ViewTransform v = make_view();
  const float expected = length(v.screen_to_world({100.0f, 50.0f}));
  EXPECT_NEAR(v.visible_radius_mm(), expected, 0.5f);
}

}  // namespace
}  // namespace ydscope::ui
