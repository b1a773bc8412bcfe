// The first window fits the screen it opens on, and the sidebar leaves the view most of it.
#include "ui/view/window/window_fit.h"

#include <gtest/gtest.h>

namespace ydscope::ui {
namespace {

void expect_inside(ScreenRect r, ScreenRect area) {
  EXPECT_GE(r.x, area.x);
  EXPECT_GE(r.y, area.y);
  EXPECT_LE(r.x + r.width, area.x + area.width);
  EXPECT_LE(r.y + r.height, area.y + area.height);
}

TEST(WindowFit, ASmallScreenGetsAWindowInsideItsWorkArea) {
  const ScreenRect area{0, 0, 1024, 600};
  const ScreenRect r = first_window_rect(area, 1.0f);
  expect_inside(r, area);
  EXPECT_EQ(r.width, 1024);
  EXPECT_EQ(r.height, 600);
  EXPECT_TRUE(window_was_shrunk(area, 1.0f)) << "maximised, so a window manager fits its title bar in too";
}

TEST(WindowFit, APanelTakesPartOfTheScreen) {
  const ScreenRect area{0, 27, 1366, 741};  // a top panel of 27 px on a 1366x768 laptop
  const ScreenRect r = first_window_rect(area, 1.0f);
  expect_inside(r, area);
  EXPECT_EQ(r.width, 1280);
  EXPECT_EQ(r.height, 741);
  EXPECT_EQ(r.x, 43) << "centred across";
  EXPECT_TRUE(window_was_shrunk(area, 1.0f));
}

TEST(WindowFit, ALargeScreenGetsThePreferredSizeCentred) {
  const ScreenRect area{0, 0, 1920, 1080};
  const ScreenRect r = first_window_rect(area, 1.0f);
  EXPECT_EQ(r.width, kPreferredWindowWidth);
  EXPECT_EQ(r.height, kPreferredWindowHeight);
  EXPECT_EQ(r.x, (1920 - 1280) / 2);
  EXPECT_EQ(r.y, (1080 - 800) / 2);
  EXPECT_FALSE(window_was_shrunk(area, 1.0f));
  EXPECT_TRUE(window_was_shrunk({0, 0, 1280, 800}, 1.0f)) << "800 px of window and a title bar do not fit 800 px";
}

TEST(WindowFit, HiDpiScalesTheWindowButStillFits) {
  const ScreenRect area{0, 0, 3840, 2160};
  const ScreenRect big = first_window_rect(area, 2.0f);
  EXPECT_EQ(big.width, 2560);
  EXPECT_EQ(big.height, 1600);
  const ScreenRect laptop{0, 0, 2560, 1600};  // 2x on a 13-inch screen: the scaled window is too big
  const ScreenRect r = first_window_rect(laptop, 2.0f);
  expect_inside(r, laptop);
  EXPECT_TRUE(window_was_shrunk(laptop, 2.0f));
}

TEST(WindowFit, NoMonitorKnownGivesThePreferredSize) {
  const ScreenRect r = first_window_rect({}, 1.0f);
  EXPECT_EQ(r.width, kPreferredWindowWidth);
  EXPECT_EQ(r.height, kPreferredWindowHeight);
}

TEST(WindowFit, TheSidebarLeavesTheViewMostOfTheWindow) {
  EXPECT_FLOAT_EQ(sidebar_width(1280.0f, 1.0f), 430.0f);
  EXPECT_LE(sidebar_width(1024.0f, 1.0f), 0.4f * 1024.0f);
  EXPECT_FLOAT_EQ(sidebar_width(2560.0f, 2.0f), 860.0f) << "twice as wide at twice the scale";
  EXPECT_LE(sidebar_max_width(1024.0f), 0.45f * 1024.0f + 0.01f);
}

}  // namespace
}  // namespace ydscope::ui
