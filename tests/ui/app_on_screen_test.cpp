// What reaches the screen. On a software renderer the app draws a streaming frame's view and only
// the boxes of the panels that changed, and copies just those to the window
// (app/gui/window_present.h), so the panels a person sees were drawn seconds earlier. Looked at
// from outside, as a person would (the X server's picture, not the app's back buffer): the panels
// are there and match the app's own picture of them, and the view on screen keeps moving.
#include <gtest/gtest.h>

#include <X11/keysym.h>

#include <cstdlib>
#include <thread>

#include "app_test_support.h"
#include "hands_on_app.h"

namespace ydscope::test {
namespace {

#ifdef YDSCOPE_APP_PATH

// Pixels of `rect` whose colour differs by more than a step of rounding between two RGB pictures
// of `width` pixels a row.
int pixels_apart(const unsigned char* a, const unsigned char* b, int width, Rect rect) {
  int apart = 0;
  for (int y = rect.y0; y < rect.y1; ++y)
    for (int x = rect.x0; x < rect.x1; ++x) {
      const std::size_t i = (static_cast<std::size_t>(y) * width + x) * 3;
      apart += std::abs(a[i] - b[i]) > 2 || std::abs(a[i + 1] - b[i + 1]) > 2 || std::abs(a[i + 2] - b[i + 2]) > 2;
    }
  return apart;
}

// Pixels of `rect` in an RGB picture of `width` pixels a row that `is_kind` picks out.
int pixels_of(const std::vector<unsigned char>& screen, int width, Rect rect, bool (*is_kind)(const unsigned char*)) {
  int count = 0;
  for (int y = rect.y0; y < rect.y1; ++y)
    for (int x = rect.x0; x < rect.x1; ++x) count += is_kind(&screen[(static_cast<std::size_t>(y) * width + x) * 3]);
  return count;
}

class AppOnScreen : public HandsOnApp {
 protected:
  // Starts the app on the virtual G6 in `dir` and waits until its own picture shows the scan;
  // then a whole screenshot of it, or an empty one (with a failure said) if that never came.
  Image start_streaming(const std::filesystem::path& dir, pid_t& app, std::set<std::string>& seen) {
    app = spawn_in(dir, {YDSCOPE_APP_PATH, "--sim", "G6"});
    if (!hands().find_window("ydscope", std::chrono::seconds(30))) {
      ADD_FAILURE() << "no ydscope window appeared";
      return {};
    }
    const int points = screenshot_until(
        app, dir, seen,
        [](const Image& image) {
          return count_pixels(image, {kViewLeft, 0, image.width, image.height}, is_point_pixel);
        },
        [](int n) { return n > 300; }, std::chrono::seconds(30));
    if (points <= 300) {
      ADD_FAILURE() << "the view never showed the virtual lidar's scan";
      return {};
    }
    return screenshot_of(app, dir, seen);
  }
};

TEST_F(AppOnScreen, ThePanelsDrawnOnceStayRightOnScreenWhileTheViewMoves) {
  X11Hands& hands = this->hands();
  const std::filesystem::path dir = fresh_temp_dir("ydscope-on-screen");
  pid_t app = -1;
  std::set<std::string> seen;
  // Streaming: the app's own picture has the virtual lidar's points.
  const Image reference = start_streaming(dir, app, seen);
  ASSERT_TRUE(reference);
  const int width = reference.width, height = reference.height;

  // A second and a half of streaming frames after the screenshot's whole one: dozens drawn in part.
  std::this_thread::sleep_for(std::chrono::milliseconds(1500));
  const std::vector<unsigned char> screen = hands.look_at_screen(width, height);
  const Image now = screenshot_of(app, dir, seen);  // the app's own picture of the same moment
  std::this_thread::sleep_for(std::chrono::milliseconds(700));
  const std::vector<unsigned char> later = hands.look_at_screen(width, height);
  ASSERT_EQ(screen.size(), static_cast<std::size_t>(width) * height * 3) << "the X server gave no picture";
  ASSERT_EQ(later.size(), screen.size());
  ASSERT_TRUE(now);

  const Rect panels{0, 0, kViewLeft - 24, height};
  const Rect view{kViewLeft, 0, width, height};
  const int panel_pixels = (panels.x1 - panels.x0) * (panels.y1 - panels.y0);
  EXPECT_GT(pixels_of(screen, width, panels, is_text_pixel), 2000) << "the panels' words are not on screen";
  // A figure or two may have changed between the look and the app's picture; nothing more.
  EXPECT_LT(pixels_apart(screen.data(), now.pixels.get(), width, panels), panel_pixels / 100)
      << "the panels on screen are not the app's";
  EXPECT_GT(pixels_of(screen, width, view, is_point_pixel), 300) << "the scan is not on screen";
  EXPECT_GT(pixels_apart(screen.data(), later.data(), width, view), 300) << "the view on screen stood still";

  EXPECT_EQ(stop_process(app, SIGTERM), 0);
  if (!HasFailure() && !std::getenv("YDSCOPE_KEEP_TEST_PNGS")) std::filesystem::remove_all(dir);
}

// Between two laps only the boxes round the points are drawn again (where they were and where they
// are), over the last picture, with the grid laid from a picture of its own. A point left behind,
// a box of grid missing or a box drawn twice would stay on screen. After seconds of the demo
// scene (every lap's points land elsewhere) drawn in parts, the view is paused: what the X server
// then shows must be what the app draws whole.
TEST_F(AppOnScreen, AViewDrawnInPartsIsTheViewDrawnWhole) {
  X11Hands& hands = this->hands();
  const std::filesystem::path dir = fresh_temp_dir("ydscope-in-parts");
  pid_t app = -1;
  std::set<std::string> seen;
  const Image first = start_streaming(dir, app, seen);
  ASSERT_TRUE(first);
  const int width = first.width, height = first.height;
  // Three seconds of laps and fades drawn in parts, then P: the laps stop and the fade settles.
  std::this_thread::sleep_for(std::chrono::seconds(3));
  hands.tap(XK_p, 1);
  std::this_thread::sleep_for(std::chrono::milliseconds(700));
  const std::vector<unsigned char> screen = hands.look_at_screen(width, height);
  const Image whole = screenshot_of(app, dir, seen);
  ASSERT_EQ(screen.size(), static_cast<std::size_t>(width) * height * 3) << "the X server gave no picture";
  ASSERT_TRUE(whole);

  // The status line at the view's foot reads the clock ("last lap ... ago"); the rest must agree.
  const Rect view{kViewLeft, 0, width, height - 60};
  EXPECT_GT(pixels_of(screen, width, view, is_point_pixel), 300) << "the scan is not on screen";
  EXPECT_LT(pixels_apart(screen.data(), whole.pixels.get(), width, view), 20)
      << "the view drawn in parts is not the view drawn whole";

  EXPECT_EQ(stop_process(app, SIGTERM), 0);
  if (!HasFailure() && !std::getenv("YDSCOPE_KEEP_TEST_PNGS")) std::filesystem::remove_all(dir);
}

#endif

}  // namespace
}  // namespace ydscope::test
