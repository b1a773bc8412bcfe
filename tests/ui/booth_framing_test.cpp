// The booth view frames the scene it sees (issue 30): a stand 4.5 m wide and 3 m deep fills a wide
// screen instead of sitting small inside rings sized for its farthest corner, a door onto a far
// hall does not widen the view, and a visitor walking close does not shrink it. Also the live
// figure: visitors counted as runs of returns closer than the room, and the nearest one's range.
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "ui/view/geometry/grid_layout.h"
#include "ui/view/geometry/view_transform.h"
#include "ui/view/scene/booth_figure.h"
#include "ui/view/scene/booth_framing.h"
#include "ui/view/settings/settings.h"

namespace ydscope::ui {
namespace {

constexpr float kHalfWide = 2250.0f, kHalfDeep = 1500.0f;  // the stand, in the view's x (right) and y (up)

// Range to the stand's walls at `angle` (as drawn: polar_to_world), a door onto a 9 m hall at
// 40 to 48 degrees, and people (each 6 degrees wide at their range) where asked.
Lap stand_lap(std::initializer_list<std::pair<float, float>> people = {}) {
  Lap lap;
  for (int i = 0; i < 1440; ++i) {
    const float angle = static_cast<float>(i) * 0.25f;
    const Vec2 d = polar_to_world(angle, 1.0f);
    float range = std::min(kHalfWide / std::max(std::abs(d.x), 1e-6f), kHalfDeep / std::max(std::abs(d.y), 1e-6f));
    if (angle >= 40.0f && angle < 48.0f) range = 9000.0f;
    for (const auto& [at_deg, person_mm] : people)
      if (std::abs(angle - at_deg) < 3.0f) range = person_mm;
    lap.points.push_back({angle, range, PointFlag::None});
  }
  return lap;
}

MotionBackground learned_stand() {
  MotionBackground room;
  for (std::size_t i = 0; i < MotionBackground::kLaps; ++i) room.add_lap(stand_lap());
  return room;
}

TEST(BoothFraming, TheStandFillsAWideScreen) {
  const MotionBackground room = learned_stand();
  const Vec2 screen{1920.0f, 1080.0f};
  const float framed = booth_frame_range_mm(room, screen);
  ViewTransform view;
  view.set_viewport({0.0f, 0.0f}, screen);
  view.fit_range(framed);
  // Every wall of the stand on screen, and the stand at least four fifths of the screen tall or wide.
  int outside = 0;
  float top = screen.y, bottom = 0.0f, left = screen.x, right = 0.0f;
  for (const LapPoint& p : stand_lap().points) {
    if (p.range_mm > 5000.0f) continue;  // the door
    const Vec2 s = view.world_to_screen(polar_to_world(p.angle_deg, p.range_mm));
    outside += view.contains_screen(s) ? 0 : 1;
    top = std::min(top, s.y), bottom = std::max(bottom, s.y), left = std::min(left, s.x), right = std::max(right, s.x);
  }
  EXPECT_EQ(outside, 0) << "walls off screen at a fit of " << framed << " mm";
  EXPECT_GT(std::max((bottom - top) / screen.y, (right - left) / screen.x), 0.8f) << "the stand sits small";
  // What the ordinary auto-range fits (the lap's 93rd percentile, a tenth more) leaves it much smaller.
  const Lap lap = stand_lap();
  EXPECT_LT(framed, robust_max_range_mm(lap.points, 0.93f) * 1.1f * 0.7f);
}

TEST(BoothFraming, AVisitorCloseByDoesNotShrinkItAndNothingBeforeTheRoomIsLearned) {
  MotionBackground room = learned_stand();
  const float framed = booth_frame_range_mm(room, {1920.0f, 1080.0f});
  room.add_lap(stand_lap({{180.0f, 600.0f}}));
  EXPECT_FLOAT_EQ(booth_frame_range_mm(room, {1920.0f, 1080.0f}), framed);
  EXPECT_EQ(booth_frame_range_mm(MotionBackground{}, {1920.0f, 1080.0f}), 0.0f);
}

TEST(BoothFigure, CountsVisitorsAndTheNearest) {
  const MotionBackground room = learned_stand();
  const VisitorCount none = count_visitors(stand_lap(), room);
  EXPECT_EQ(none.visitors, 0);
  EXPECT_FALSE(none.nearest_mm);
  EXPECT_EQ(booth_figure_text(BoothFigureKind::Nearest, none), "no one near");
  const VisitorCount two = count_visitors(stand_lap({{170.0f, 1200.0f}, {200.0f, 900.0f}}), room);
  EXPECT_EQ(two.visitors, 2);
  EXPECT_FLOAT_EQ(*two.nearest_mm, 900.0f);
  EXPECT_EQ(booth_figure_text(BoothFigureKind::Visitors, two), "2 visitors");
  EXPECT_EQ(booth_figure_text(BoothFigureKind::Nearest, two), "nearest 0.9 m");
  // Someone standing across 0 degrees is one visitor, not two.
  const VisitorCount across = count_visitors(stand_lap({{0.5f, 1000.0f}, {359.5f, 1000.0f}}), room);
  EXPECT_EQ(across.visitors, 1);
  EXPECT_EQ(booth_figure_text(BoothFigureKind::Visitors, across), "1 visitor");
  EXPECT_EQ(booth_figure_text(BoothFigureKind::None, across), "");
}

TEST(BoothFigure, SettingsWordsGoBothWays) {
  for (const BoothFigureKind kind : {BoothFigureKind::None, BoothFigureKind::Visitors, BoothFigureKind::Nearest})
    EXPECT_EQ(booth_figure_from_word(booth_figure_word(kind)), kind);
  EXPECT_FALSE(booth_figure_from_word("people"));
  ViewSettings s;
  s.booth_title = "Come and walk past the G6";
  s.booth_figure = BoothFigureKind::Nearest;
  EXPECT_EQ(parse_settings(format_settings(s)), s);
  std::vector<std::string> notes;
  EXPECT_EQ(parse_settings("booth_figure = people\n", &notes).booth_figure, BoothFigureKind::None);
  ASSERT_EQ(notes.size(), 1u);
  EXPECT_EQ(notes[0], "booth_figure = people is left out: it takes none, visitors or nearest");
}

}  // namespace
}  // namespace ydscope::ui
