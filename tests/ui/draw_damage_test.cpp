// Where the panels' picture changed between two frames: nothing when a frame repeats the last, so
// the app skips it; a small box round a figure that changed, so the app draws only that. The real
// sidebar panels lay out in a headless ImGui context.
#include <gtest/gtest.h>

#include <imgui.h>

#include <cmath>
#include <optional>
#include <vector>

#include "tests/ui/headless_imgui.h"
#include "ui/panels/panels.h"
#include "ui/render/draw_damage.h"

namespace ydscope::ui {
namespace {

// One frame of the sidebar for `m`, and where it differs from the frame before.
std::optional<std::vector<DisplayBox>> sidebar_frame(DrawDamage& damage, UiModel& m, ViewSettings& settings) {
  PanelEdits edits;
  ImGui::GetIO().DeltaTime = 1.0f / 60.0f;
  ImGui::NewFrame();
  draw_sidebar(m, edits, settings);
  ImGui::Render();
  return damage.update(*ImGui::GetDrawData());
}

TEST(DrawDamage, AFrameThatRepeatsTheLastHasNoneAndAChangedFigureOnlyItsOwnBox) {
  HeadlessImGui imgui(1280.0f, 800.0f);
  UiModel m;
  m.snap.state = LinkState::Reconnecting;
  m.snap.scan_hz = 8.0;
  ViewSettings settings;
  DrawDamage damage;
  EXPECT_FALSE(sidebar_frame(damage, m, settings)) << "the first frame has nothing to be compared with";
  sidebar_frame(damage, m, settings);  // the layout settles
  const auto same = sidebar_frame(damage, m, settings);
  ASSERT_TRUE(same);
  EXPECT_TRUE(same->empty()) << "nothing changed, so the frame need not be drawn";

  m.snap.scan_hz = 8.1;  // one digit of one number in the Scan frequency panel
  const auto new_rate = sidebar_frame(damage, m, settings);
  ASSERT_TRUE(new_rate);
  ASSERT_EQ(new_rate->size(), 1u);
  const DisplayBox box = new_rate->front();
  EXPECT_LT(box.y1 - box.y0, 30.0f) << "one line of text";
  EXPECT_LT(box.x1 - box.x0, 120.0f) << "one figure, not the panel";
  EXPECT_LT(box.x1, 500.0f) << "in the sidebar";

  m.snap.state = LinkState::Scanning;  // a word and its colour
  const auto new_state = sidebar_frame(damage, m, settings);
  ASSERT_TRUE(new_state);
  EXPECT_FALSE(new_state->empty());
  EXPECT_FALSE(new_state->front().overlaps(box)) << "the state is written elsewhere than the rate";
}

TEST(DrawDamage, TwoFiguresThatChangedApartAreTwoSmallBoxesNotOneRoundAllBetween) {
  HeadlessImGui imgui(1280.0f, 800.0f);
  UiModel m;
  m.snap.state = LinkState::Scanning;
  m.snap.link = "/dev/ttyUSB0 at 512000 baud";
  m.snap.scan_hz = 8.0;
  ViewSettings settings;
  DrawDamage damage;
  for (int frame = 0; frame < 3; ++frame) sidebar_frame(damage, m, settings);
  m.snap.scan_hz = 8.1;                         // the Scan frequency panel, near the foot of the tab
  m.snap.link = "/dev/ttyUSB1 at 512000 baud";  // the Connection panel, at its head
  const auto both = sidebar_frame(damage, m, settings);
  ASSERT_TRUE(both);
  ASSERT_EQ(both->size(), 2u);
  for (const DisplayBox& box : *both) EXPECT_LT(box.y1 - box.y0, 30.0f) << "one line of text each";
  EXPECT_GT(std::abs((*both)[1].y0 - (*both)[0].y0), 100.0f) << "the two lines lie apart";
}

// Two minutes of a G6 at 8 Hz, up to `until_s`, as the Plots panel is fed.
void fill_plots(RunPlots& plots, double until_s) {
  for (double t = until_s - 130.0; t <= until_s; t += 0.125) {
    plots.add_lap({t, 8.0 + 0.05 * std::sin(t), 8.0, static_cast<std::size_t>(2200 + 40 * std::sin(3 * t))});
    plots.add_latency_ms(15.0 + 5.0 * std::sin(7 * t), t);
    plots.sample_counters({t, 40000.0 + 500.0 * std::sin(t), 0, 0, 0});
  }
}

TEST(DrawDamage, LivePlotsRepeatWithinAPixelColumnAndMoveAWholeColumnAtATime) {
  HeadlessImGui imgui(1280.0f, 800.0f);
  UiModel m;
  m.snap.state = LinkState::Scanning;
  fill_plots(m.plots, 1000.0);
  m.now_s = 1000.0;
  m.show_sidebar_tab = static_cast<int>(SidebarTab::Statistics);
  ViewSettings settings;
  DrawDamage damage;
  for (int frame = 0; frame < 3; ++frame) sidebar_frame(damage, m, settings);
  ASSERT_EQ(settings.sidebar_tab, SidebarTab::Statistics);
  // Two minutes over some 330 columns: a column is about a third of a second, so of ten frames
  // a hundredth of a second apart at most one crosses into the next column.
  int moved = 0;
  for (int frame = 0; frame < 10; ++frame) {
    m.now_s += 0.01;
    const auto boxes = sidebar_frame(damage, m, settings);
    ASSERT_TRUE(boxes);
    moved += boxes->empty() ? 0 : 1;
  }
  EXPECT_LE(moved, 1) << "the plots moved by less than a pixel, yet were drawn otherwise";
  m.now_s += 1.0;  // three columns on: the lines move, under the still frame and ticks
  const auto boxes = sidebar_frame(damage, m, settings);
  ASSERT_TRUE(boxes);
  ASSERT_FALSE(boxes->empty());
  for (const DisplayBox& box : *boxes) EXPECT_GT(box.y0, 300.0f) << "only the plots, under the Statistics panel";
}

TEST(DrawDamage, ADrawListMoreOrLessCannotBeComparedSoAllOfItChanged) {
  HeadlessImGui imgui(1280.0f, 800.0f);
  UiModel m;
  ViewSettings settings;
  DrawDamage damage;
  sidebar_frame(damage, m, settings);
  sidebar_frame(damage, m, settings);
  ImGui::NewFrame();
  ImGui::Begin("another window");
  ImGui::TextUnformatted("a window the last frame did not have");
  ImGui::End();
  ImGui::Render();
  EXPECT_FALSE(damage.update(*ImGui::GetDrawData()));
  damage.forget();
  EXPECT_FALSE(damage.update(*ImGui::GetDrawData())) << "after forget() the next frame is compared with nothing";
  EXPECT_TRUE(damage.update(*ImGui::GetDrawData()));
}

TEST(ScreenBoxes, OverlappingBoxesMergeAndPixelsCountFromTheBottom) {
  const std::vector<DisplayBox> merged =
      merged_boxes({{0, 0, 10, 10}, {5, 5, 20, 20}, {100, 100, 110, 120}, {3, 3, 3, 9}});
  ASSERT_EQ(merged.size(), 2u) << "the empty box goes, the two overlapping become one";
  EXPECT_EQ(merged[0], (DisplayBox{0, 0, 20, 20}));
  EXPECT_EQ(merged[1], (DisplayBox{100, 100, 110, 120}));
  EXPECT_TRUE(merged_boxes({{0, 0, 10, 10}, {10, 0, 20, 10}}).size() == 2u) << "touching is not overlapping";
  // 800 pixels high: the display's rows 100..120 are GL's 680..700; a fraction rounds outwards.
  EXPECT_EQ(to_pixels({10.5f, 100.0f, 20.0f, 120.0f}, 1.0f, 800), (PixelBox{10, 680, 10, 20}));
  EXPECT_EQ(to_pixels({10.0f, 100.0f, 20.0f, 120.0f}, 2.0f, 1600), (PixelBox{20, 1360, 20, 40}));
  EXPECT_TRUE(to_pixels({5, 5, 5, 9}, 1.0f, 800).empty());
}

}  // namespace
}  // namespace ydscope::ui
