// The booth view's calm: banners fade, the pointer hides at rest, persistence is long; the
// windowed view keeps each as it was.
#include "ui/view/status/booth_calm.h"

#include <gtest/gtest.h>

namespace ydscope::ui {
namespace {

TEST(BoothCalm, ABannerStaysWholeThenFadesOnlyInTheBoothView) {
  EXPECT_FLOAT_EQ(banner_opacity(0.0, true), 1.0f);
  EXPECT_FLOAT_EQ(banner_opacity(kBannerHoldSeconds, true), 1.0f);
  EXPECT_NEAR(banner_opacity(kBannerHoldSeconds + kBannerFadeSeconds / 2, true), 0.5f, 1e-6);
  EXPECT_FLOAT_EQ(banner_opacity(kBannerHoldSeconds + kBannerFadeSeconds, true), 0.0f);
  EXPECT_FLOAT_EQ(banner_opacity(3600.0, true), 0.0f);
  EXPECT_FLOAT_EQ(banner_opacity(3600.0, false), 1.0f) << "the windowed view keeps its banner";
}

TEST(BoothCalm, TheViewAnimatesOnlyWhileABoothBannerFades) {
  EXPECT_FALSE(banner_fading(kBannerHoldSeconds - 0.1, true)) << "still whole";
  EXPECT_TRUE(banner_fading(kBannerHoldSeconds + 0.5 * kBannerFadeSeconds, true));
  EXPECT_FALSE(banner_fading(kBannerHoldSeconds + kBannerFadeSeconds + 0.1, true)) << "gone";
  EXPECT_FALSE(banner_fading(kBannerHoldSeconds + 0.5 * kBannerFadeSeconds, false)) << "the window never fades it";
}

TEST(BoothCalm, ThePointerHidesAtRestOnlyInTheBoothView) {
  EXPECT_FALSE(cursor_hidden(0.0, true));
  EXPECT_FALSE(cursor_hidden(kCursorRestSeconds - 0.1, true));
  EXPECT_TRUE(cursor_hidden(kCursorRestSeconds, true));
  EXPECT_FALSE(cursor_hidden(600.0, false));
}

TEST(BoothCalm, TheBoothKeepsThirtyToSixtyLaps) {
  EXPECT_EQ(booth_persistence(1), kBoothMinPersistence);
  EXPECT_EQ(booth_persistence(10), 30);
  EXPECT_EQ(booth_persistence(45), 45);
  EXPECT_EQ(booth_persistence(200), kBoothMaxPersistence);
}

TEST(BoothCalm, VisitorsAreNotToldWhichCommandListsThePorts) {
  ViewState state;
  state.dim = true;
  state.headline = "No data";
  state.subtitle = "the lidar stopped sending, last lap 12 s ago";
  state.detail = "no such device; is the lidar plugged in? 'ydscope-cli ports' lists serial ports";
  const ViewState booth = for_audience(state, true);
  EXPECT_TRUE(booth.detail.empty()) << booth.detail;
  EXPECT_EQ(booth.headline, state.headline);
  EXPECT_EQ(booth.subtitle, state.subtitle);
  EXPECT_TRUE(booth.dim);
  EXPECT_EQ(for_audience(state, false).detail, state.detail) << "the window keeps the operator's sentence";
}

}  // namespace
}  // namespace ydscope::ui
