// The hover box shows only while a person points: never for a pointer that never moved (Xvfb's,
// in --screenshot runs), not after the pointer left the window, not once it rests.
#include "ui/view/status/hover_gate.h"

#include <gtest/gtest.h>

namespace ydscope::ui {
namespace {

TEST(HoverGate, APointerThatNeverMovedShowsNoBox) {
  HoverGate gate;
  for (int frame = 0; frame < 100; ++frame) {
    gate.update(true, false, frame * 0.016);
    EXPECT_FALSE(gate.visible()) << "frame " << frame;
  }
}

TEST(HoverGate, MovingShowsItLeavingHidesIt) {
  HoverGate gate;
  gate.update(true, true, 1.0);
  EXPECT_TRUE(gate.visible());
  gate.update(true, false, 1.5);
  EXPECT_TRUE(gate.visible()) << "a short rest keeps it";
  gate.update(false, false, 1.6);
  EXPECT_FALSE(gate.visible()) << "the pointer left the window";
  gate.update(true, false, 1.7);
  EXPECT_FALSE(gate.visible()) << "back in the window, but no move since it left";
  gate.update(true, true, 1.8);
  EXPECT_TRUE(gate.visible());
}

TEST(HoverGate, ARestingPointerLosesTheBoxAndAMoveBringsItBack) {
  HoverGate gate;
  gate.update(true, true, 10.0);
  gate.update(true, false, 10.0 + HoverGate::kIdleSeconds - 0.1);
  EXPECT_TRUE(gate.visible());
  gate.update(true, false, 10.0 + HoverGate::kIdleSeconds + 0.1);
  EXPECT_FALSE(gate.visible());
  gate.update(true, true, 20.0);
  EXPECT_TRUE(gate.visible());
}

TEST(HoverGate, DisabledForScreenshotsWhateverThePointerDoes) {
  HoverGate gate(false);
  gate.update(true, true, 1.0);
  EXPECT_FALSE(gate.visible());
}

}  // namespace
}  // namespace ydscope::ui
