// Auto-range refits on a real change of the scan, and at once when it is turned back on after a
// wheel zoom (the A key or the checkbox), even though the scan itself did not change.
#include "ui/view/geometry/auto_range_fit.h"

#include <gtest/gtest.h>

namespace ydscope::ui {
namespace {

TEST(AutoRangeFit, FitsTheFirstLapAndIgnoresLapNoise) {
  AutoRangeFit fit;
  EXPECT_EQ(fit.update(true, 0.0f), std::nullopt) << "no lap yet: nothing to fit";
  EXPECT_EQ(fit.update(true, 8000.0f), 8000.0f);
  EXPECT_EQ(fit.update(true, 8600.0f), std::nullopt) << "7 % is noise";
  EXPECT_EQ(fit.update(true, 12000.0f), 12000.0f) << "50 % is a new scene";
  EXPECT_FLOAT_EQ(fit.fitted_mm(), 12000.0f);
}

// The bug: after a wheel zoom turned auto-range off, turning it on again left the view zoomed,
// because the wanted range equalled the one fitted before the zoom.
TEST(AutoRangeFit, TurningItBackOnRefitsAtOnceWithTheSameScan) {
  AutoRangeFit fit;
  ASSERT_EQ(fit.update(true, 8000.0f), 8000.0f);
  EXPECT_EQ(fit.update(false, 8000.0f), std::nullopt) << "off after the wheel zoom: the user's view stays";
  EXPECT_EQ(fit.update(false, 8000.0f), std::nullopt);
  EXPECT_EQ(fit.update(true, 8000.0f), 8000.0f) << "on again: refit in that very frame";
  EXPECT_EQ(fit.update(true, 8000.0f), std::nullopt) << "and then only on real changes";
}

TEST(AutoRangeFit, TurnedOnBeforeAnyLapFitsTheFirstOne) {
  AutoRangeFit fit;
  EXPECT_EQ(fit.update(false, 0.0f), std::nullopt);
  EXPECT_EQ(fit.update(true, 0.0f), std::nullopt);
  EXPECT_EQ(fit.update(true, 5000.0f), 5000.0f);
}

TEST(AutoRangeFit, AResizeRefitsTheSameRange) {
  AutoRangeFit fit;
  ASSERT_EQ(fit.update(true, 8000.0f), 8000.0f);
  fit.forget();
  EXPECT_EQ(fit.update(true, 8000.0f), 8000.0f);
}

}  // namespace
}  // namespace ydscope::ui
