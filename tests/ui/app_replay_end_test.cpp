// A replay with loop off (--once) stops at the recording's end and says so: the cloud dims under
// a large overlay, the status line takes the calm colour of information (blue), never the orange
// of a link in trouble ("reconnecting", "stalled"), and the picture stays ended: no restart.
#include <gtest/gtest.h>

#include "app_test_support.h"
#include "test_data.h"

namespace ydscope::test {
namespace {

#ifdef YDSCOPE_APP_PATH

// The status line's words at the bottom left of the view, in its severity's colour.
bool info_blue(const unsigned char* p) { return p[2] > 230 && p[0] > 100 && p[0] < 170 && p[1] > 160 && p[1] < 210; }
bool warning_orange(const unsigned char* p) { return p[0] > 230 && p[1] > 170 && p[1] < 225 && p[2] < 130; }

struct EndReading {
  int overlay_words = 0;
  int blue_status = 0;
  int orange_status = 0;
};

EndReading read(const Image& image, int view_left) {
  EndReading r;
  const int cx = (view_left + image.width) / 2;
  const int cy = image.height / 2;
  r.overlay_words = count_pixels(image, {cx - 320, cy - 90, cx + 320, cy + 90}, is_white_pixel);
  // The status line's band at the bottom (the colour legend sits just above it, in the corner).
  const Rect status_band{view_left, image.height - 40, image.width, image.height};
  r.blue_status = count_pixels(image, status_band, info_blue);
  r.orange_status = count_pixels(image, status_band, warning_orange);
  return r;
}

TEST(AppReplayEnd, ReplayOnceStopsAtTheEndAndSaysSo) {
  if (!std::getenv("DISPLAY")) GTEST_SKIP() << "no DISPLAY: run under xvfb-run (scripts/test does)";
  const std::string recording = (assets_dir() / "demo-g6.ydrec").string();
  ASSERT_TRUE(std::filesystem::exists(recording)) << recording;
  const std::filesystem::path dir = fresh_temp_dir("ydscope-replay-end");
  const pid_t app = spawn_in(dir, {YDSCOPE_APP_PATH, "--replay", recording, "--speed", "8", "--once"});
  std::set<std::string> seen;

  // The view sits right of the panels, which take at most 40 % of the window.
  const auto ended = [](const EndReading& r) { return r.overlay_words > 1500 && r.blue_status > 30; };
  // Before its first lap the view says "No data ... waiting" in the same large overlay and the same
  // information blue, so the end only counts once the replay has been seen playing (no overlay).
  EndReading last;
  int view_left = 0;
  bool played = false;
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(60);
  while (std::chrono::steady_clock::now() < deadline) {
    const Image image = screenshot_of(app, dir, seen);
    if (!image) continue;
    view_left = image.width * 2 / 5;
    last = read(image, view_left);
    if (last.overlay_words < 500) played = true;
    if (played && ended(last)) break;
  }
  EXPECT_TRUE(played) << "the replay's laps were never seen without an overlay";
  EXPECT_GT(last.overlay_words, 1500) << "no large overlay after the recording's end";
  EXPECT_GT(last.blue_status, 30) << "the status line does not say the replay ended (information blue)";
  EXPECT_LT(last.orange_status, 10) << "the status line speaks of a link in trouble";

  // Ended stays ended: it does not go round again nor try to reconnect.
  for (int i = 0; i < 3; ++i) {
    const Image image = screenshot_of(app, dir, seen);
    ASSERT_TRUE(image) << "the app stopped answering after the replay ended";
    const EndReading again = read(image, view_left);
    EXPECT_GT(again.overlay_words, 1500) << "screenshot " << i << " after the end: the overlay went away";
    EXPECT_GT(again.blue_status, 30) << "screenshot " << i;
    EXPECT_LT(again.orange_status, 10) << "screenshot " << i;
  }
  EXPECT_EQ(stop_process(app, SIGTERM), 0);
  if (!HasFailure() && !std::getenv("YDSCOPE_KEEP_TEST_PNGS")) std::filesystem::remove_all(dir);
}

#endif

}  // namespace
}  // namespace ydscope::test
