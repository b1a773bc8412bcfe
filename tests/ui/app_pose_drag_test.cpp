// Posing a source by hand: with two lidars in one view, Alt+drag on the view moves the selected
// source's cloud with the pointer and leaves the other where it was, N selects the other one for
// the next drag, and the poses they end at are the ones settings.ini remembers: a next run that
// names no source starts the same two lidars again, each where it was left.
#include <gtest/gtest.h>

#include <fstream>
#include <sstream>

// Ours before Xlib's, whose macros (None, ...) would rename our enumerators.
#include "ui/view/settings/settings.h"
#include "ui/view/scene/source_set.h"

#include "app_test_support.h"
#include "hands_on_app.h"

namespace ydscope::test {
namespace {

#ifdef YDSCOPE_APP_PATH

bool near_hue(const unsigned char* p, ui::Rgba8 c) {
  // Bright and closest to this colour: enough to tell the palette's first two apart.
  if (!is_point_pixel(p)) return false;
  const int d = std::abs(p[0] - c.r) + std::abs(p[1] - c.g) + std::abs(p[2] - c.b);
  return d < 150;
}

// Mean x of the view's pixels of `colour`, and how many there are.
std::pair<double, int> centroid_x(const Image& image, ui::Rgba8 colour) {
  double sum = 0;
  int n = 0;
  for (int y = 0; y < image.height; ++y)
    for (int x = kViewLeft; x < image.width; ++x)
      if (near_hue(image.at(x, y), colour)) {
        sum += x;
        ++n;
      }
  return {n ? sum / n : 0.0, n};
}

class AppPoseDrag : public HandsOnApp {};

TEST_F(AppPoseDrag, AltDragMovesTheSelectedCloudOnlyNSelectsTheNextAndTheNextRunStartsThemThere) {
  X11Hands& hands = this->hands();
  const std::filesystem::path dir = fresh_temp_dir("ydscope-pose-drag");
  hands.move_pointer(900, 790);  // parked low in the view, away from where the drag starts
  const pid_t app = spawn_in(dir, {YDSCOPE_APP_PATH, "--sim", "G1,G6"});
  ASSERT_TRUE(hands.find_window("ydscope", std::chrono::seconds(30)));
  const ui::Rgba8 first = ui::source_colour(0), second = ui::source_colour(1);
  std::set<std::string> seen;
  struct Reading {
    std::pair<double, int> first, second;
  };
  const auto read = [&](const Image& image) { return Reading{centroid_x(image, first), centroid_x(image, second)}; };
  const auto both_drawn = [](const Reading& r) { return r.first.second > 2000 && r.second.second > 2000; };
  const Reading before = screenshot_until(app, dir, seen, read, both_drawn, std::chrono::seconds(30));
  ASSERT_TRUE(both_drawn(before)) << "the two clouds never showed";

  // Alt held, the left button down, 200 px to the right in steps a frame can see, let go.
  const auto alt_drag_right = [&](int y) {
    const int x0 = 800, x1 = 1000;
    hands.move_pointer(x0, y);
    hands.key_down(XK_Alt_L);
    std::this_thread::sleep_for(std::chrono::milliseconds(200));
    hands.left_button(true, x0, y);
    for (int x = x0; x <= x1; x += 10) {
      hands.move_pointer(x, y);
      std::this_thread::sleep_for(std::chrono::milliseconds(40));
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(200));
    hands.left_button(false, x1, y);
    hands.key_up(XK_Alt_L);
  };
  alt_drag_right(400);
  const auto first_moved = [&](const Reading& r) { return both_drawn(r) && r.first.first - before.first.first > 120; };
  const Reading after = screenshot_until(app, dir, seen, read, first_moved, std::chrono::seconds(10));
  EXPECT_GT(after.first.first - before.first.first, 120) << "the selected source's cloud did not follow the pointer";
  EXPECT_LT(std::abs(after.second.first - before.second.first), 30) << "the other source's cloud moved too";

  // N selects the next source: now the same drag moves the second cloud and not the first.
  hands.tap(XK_n, 1);
  std::this_thread::sleep_for(std::chrono::milliseconds(300));
  alt_drag_right(420);
  const auto second_moved = [&](const Reading& r) {
    return both_drawn(r) && r.second.first - after.second.first > 120;
  };
  const Reading last = screenshot_until(app, dir, seen, read, second_moved, std::chrono::seconds(10));
  EXPECT_GT(last.second.first - after.second.first, 120)
      << "after N the second source's cloud did not follow the pointer";
  EXPECT_LT(std::abs(last.first.first - after.first.first), 30) << "after N the first source's cloud moved too";
  EXPECT_EQ(stop_process(app, SIGTERM), 0);

  // The pose it ended at is remembered by name: a drag to the right on screen is to the robot's
  // right, so y fell from where the spread put it (2 m to the left).
  std::ifstream settings(dir / "ydscope" / "settings.ini");
  std::stringstream text;
  text << settings.rdbuf();
  const ui::ViewSettings saved = ui::parse_settings(text.str());
  ASSERT_EQ(saved.sources.size(), 2u) << text.str();
  EXPECT_EQ(saved.sources[0].name, "G1");
  EXPECT_LT(saved.sources[0].pose.y_m, ui::spread_poses(2)[0].y_m - 1.0) << text.str();
  EXPECT_EQ(saved.last_sources, (std::vector<std::string>{"G1", "G6"})) << text.str();

  // The next run names no source: the same two lidars start again, each where it was left.
  const pid_t again = spawn_in(dir, {YDSCOPE_APP_PATH});
  const auto where_left = [&](const Reading& r) {
    return both_drawn(r) && std::abs(r.first.first - last.first.first) < 30 &&
           std::abs(r.second.first - last.second.first) < 30;
  };
  const Reading restarted = screenshot_until(again, dir, seen, read, where_left, std::chrono::seconds(30));
  EXPECT_TRUE(both_drawn(restarted)) << "the last run's two lidars did not start again";
  EXPECT_LT(std::abs(restarted.first.first - last.first.first), 30) << "G1 is not where it was left";
  EXPECT_LT(std::abs(restarted.second.first - last.second.first), 30) << "G6 is not where it was left";
  EXPECT_EQ(stop_process(again, SIGTERM), 0);
  if (!HasFailure() && !std::getenv("YDSCOPE_KEEP_TEST_PNGS")) std::filesystem::remove_all(dir);
}

#endif

}  // namespace
}  // namespace ydscope::test
