// The hover box (nearest point's angle and range) is for a person pointing: it shows when the
// pointer moves onto a scan point, goes once the pointer rests, and never appears in a
// --screenshot picture, even with a pointer moving over a point while it is taken.
#include <gtest/gtest.h>

#include <cstdlib>

#include "app_test_support.h"
#include "hands_on_app.h"

namespace ydscope::test {
namespace {

#ifdef YDSCOPE_APP_PATH

struct Spot {
  int x = -1, y = -1;
};

// A scan point on the room's left wall: left of the view's centre, off the horizontal spoke.
Spot find_wall_point(const Image& image) {
  const int cy = image.height / 2;
  for (int x = image.width * 2 / 5; x < image.width / 2 + 100; ++x)
    for (int y = cy - 120; y < cy - 60; ++y)
      if (is_point_pixel(image.at(x, y))) return {x, y};
  return {};
}

// The box's near-white words sit above and right of the point.
int hover_words(const Image& image, Spot at) {
  return count_pixels(image, {at.x + 4, at.y - 50, at.x + 320, at.y - 4}, is_white_pixel);
}

class AppHover : public HandsOnApp {};

TEST_F(AppHover, TheBoxFollowsAMovingPointerAndGoesWhenItRests) {
  X11Hands& hands = this->hands();
  const std::filesystem::path dir = fresh_temp_dir("ydscope-hover");
  const pid_t app = spawn_in(dir, {YDSCOPE_APP_PATH, "--sim", "G6", "--scene", "room"});
  ASSERT_TRUE(hands.find_window("ydscope", std::chrono::seconds(30)));
  std::set<std::string> seen;
  Spot wall;
  for (int i = 0; i < 20 && wall.x < 0; ++i) {
    const Image image = screenshot_of(app, dir, seen);
    if (image) wall = find_wall_point(image);
  }
  ASSERT_GE(wall.x, 0) << "no wall point found to point at";

  hands.move_pointer(wall.x - 20, wall.y);
  hands.move_pointer(wall.x, wall.y);
  int shown = 0;
  for (int i = 0; i < 10 && shown < 60; ++i) {
    hands.move_pointer(wall.x, wall.y + (i % 2));  // still moving, as a hand does
    if (const Image image = screenshot_of(app, dir, seen)) shown = hover_words(image, wall);
  }
  EXPECT_GE(shown, 60) << "no hover box over a scan point under a moving pointer";

  // Resting: the box goes by itself (HoverGate::kIdleSeconds), with no further input.
  int rested = shown;
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(20);
  while (rested >= 20 && std::chrono::steady_clock::now() < deadline)
    if (const Image image = screenshot_of(app, dir, seen)) rested = hover_words(image, wall);
  EXPECT_LT(rested, 20) << "the hover box stays under a resting pointer";
  EXPECT_EQ(stop_process(app, SIGTERM), 0);

  // A screenshot run with a hand moving over that same wall point all along: no box.
  const std::string png = (dir / "pointed.png").string();
  const pid_t shot =
      spawn_in(dir, {YDSCOPE_APP_PATH, "--sim", "G6", "--scene", "room", "--screenshot", png, "--frames", "60"});
  ASSERT_TRUE(hands.find_window("ydscope", std::chrono::seconds(30)));
  int status = 0;
  for (int i = 0; waitpid(shot, &status, WNOHANG) == 0; ++i) {
    hands.move_pointer(wall.x, wall.y + (i % 2));
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  }
  ASSERT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 0) << "the screenshot run failed";
  const Image pointed = load_png(png);
  ASSERT_TRUE(pointed) << png;
  EXPECT_LT(hover_words(pointed, wall), 20) << "a hover box in a --screenshot picture";
  if (!HasFailure() && !std::getenv("YDSCOPE_KEEP_TEST_PNGS")) std::filesystem::remove_all(dir);
}

#endif

}  // namespace
}  // namespace ydscope::test
