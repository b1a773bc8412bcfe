// The unit's 0 degrees and sweep as the view marks them: a lone lidar's 0 points down the screen
// and its sweep runs clockwise; turned with its yaw, and the other way round when upside down.
#include "ui/view/geometry/unit_marks.h"

#include <gtest/gtest.h>

namespace ydscope::ui {
namespace {

ViewTransform view_of_size() {
  ViewTransform view;
  view.set_viewport({0.0f, 0.0f}, {800.0f, 600.0f});
  view.fit_range(5000.0f);
  return view;
}

// Positive: the arrow turns clockwise on screen (screen y grows downwards).
float turn_of(const UnitMarks& m) {
  float total = 0.0f;
  for (std::size_t i = 1; i < m.sweep.size(); ++i) {
    const Vec2 a = m.sweep[i - 1] - m.centre, b = m.sweep[i] - m.centre;
    total += a.x * b.y - a.y * b.x;
  }
  return total;
}

TEST(UnitMarks, ALoneLidarsZeroPointsDownAndItSweepsClockwise) {
  const ViewTransform view = view_of_size();
  const UnitMarks m = unit_marks(view, {});
  EXPECT_NEAR(m.centre.x, 400.0f, 0.01f);
  EXPECT_NEAR(m.centre.y, 300.0f, 0.01f);
  EXPECT_NEAR(m.zero_to.x, m.centre.x, 0.01f);
  EXPECT_GT(m.zero_to.y, m.zero_from.y);  // down the screen
  EXPECT_GT(m.zero_label.y, m.zero_to.y);
  EXPECT_GT(turn_of(m), 0.0f);
  // The arrowhead leads on from the shaft's end, the way it turns.
  EXPECT_GT(length(m.head_tip - m.sweep.front()), length(m.sweep.back() - m.sweep.front()));
}

TEST(UnitMarks, TheyTurnWithTheYawAndMirrorUpsideDown) {
  const ViewTransform view = view_of_size();
  // Yaw 90 (counter-clockwise): the unit's 0, which pointed down, points right.
  const UnitMarks turned = unit_marks(view, {0, 0, 90, false});
  EXPECT_GT(turned.zero_to.x, turned.zero_from.x + 10.0f);
  EXPECT_NEAR(turned.zero_to.y, turned.centre.y, 0.5f);
  EXPECT_GT(turn_of(turned), 0.0f);
  const UnitMarks flipped = unit_marks(view, {1.0, 0, 0, true});
  EXPECT_LT(flipped.centre.y, 300.0f);  // 1 m forward: up the screen
  EXPECT_GT(flipped.zero_to.y, flipped.zero_from.y);
  EXPECT_LT(turn_of(flipped), 0.0f);  // counter-clockwise on screen
  // An angle offset turns the tick: the unit's 0 is where 0 + offset would be.
  const UnitMarks offset = unit_marks(view, {0, 0, 0, false, 90});
  EXPECT_LT(offset.zero_to.x, offset.centre.x - 10.0f);  // where the unit's 90 is: left
}

}  // namespace
}  // namespace ydscope::ui
