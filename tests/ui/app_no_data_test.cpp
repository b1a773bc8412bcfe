// A bad day under Xvfb: the app shows a virtual lidar that runs in another process; when that
// process is killed the picture must dim and say so in large words, and when the lidar comes back
// on the same port the live picture must return by itself.
#include <gtest/gtest.h>

#include "app_test_support.h"

namespace ydscope::test {
namespace {

#ifdef YDSCOPE_APP_PATH

// The view is right of the panels (~430 px of 1280); the overlay box sits at its centre.

struct NoDataReading {
  int points = 0;         // saturated scan-point pixels inside the rings
  int overlay_words = 0;  // near-white pixels in the band where the overlay writes
  int sidebar_green = 0;  // the panels' "all is well" green (state, health lamp and status words)
};

// The panels' green words and lamps (ImGui colours 0.35, 0.9, 0.55 and 70, 200, 110).
bool is_all_is_well_green(const unsigned char* p) { return p[1] > 170 && p[1] > p[0] + 80 && p[1] > p[2] + 40; }

NoDataReading read(const Image& image) {
  NoDataReading r;
  r.points = points_in_rings(image, kViewLeft);
  r.sidebar_green = count_pixels(image, {0, 0, kViewLeft - 20, image.height}, is_all_is_well_green);
  const int cx = (kViewLeft + image.width) / 2;
  const int cy = image.height / 2;
  r.overlay_words = count_pixels(image, {cx - 320, cy - 90, cx + 320, cy + 90}, is_white_pixel);
  return r;
}

TEST(AppBadDay, KilledLidarDimsTheViewWithAnOverlayAndRecovers) {
  if (!std::getenv("DISPLAY")) GTEST_SKIP() << "no DISPLAY: run under xvfb-run (scripts/test does)";
  const std::filesystem::path dir = fresh_temp_dir("ydscope-bad-day");
  const std::string link = (dir / "lidar").string();
  const std::vector<std::string> sim_argv{YDSCOPE_CLI_PATH, "sim", "--model", "G6", "--scene", "demo", "--pty", link};
  pid_t sim = spawn_in(dir, sim_argv);
  ASSERT_TRUE(wait_for_path(link, std::chrono::seconds(15))) << "the virtual lidar did not make " << link;
  const pid_t app = spawn_in(dir, {YDSCOPE_APP_PATH, "--port", link, "--model", "G6"});
  std::set<std::string> seen;

  const auto live = [](const NoDataReading& r) { return r.points > 300 && r.overlay_words < 400; };
  const NoDataReading before = screenshot_until(app, dir, seen, read, live, std::chrono::seconds(30));
  EXPECT_GT(before.points, 300) << "the live scan never showed";
  EXPECT_LT(before.overlay_words, 400) << "a live view must carry no overlay";

  // A crash, not a clean exit: the pseudo-terminal's other end vanishes mid-stream.
  stop_process(sim, SIGKILL);
  // At once: the killed sim's link names a pty number that another test's lidar may take next,
  // and the app, reconnecting to the link, would show that one live (seen under ctest -j2).
  std::filesystem::remove(link);
  const auto dimmed = [&](const NoDataReading& r) { return r.points < before.points / 10 && r.overlay_words > 1500; };
  const NoDataReading dead = screenshot_until(app, dir, seen, read, dimmed, std::chrono::seconds(20));
  EXPECT_LT(dead.points, before.points / 10) << "the old scan stays bright after the lidar died";
  EXPECT_GT(dead.overlay_words, 1500) << "no large overlay words over the view";
  // Issue 26: the panels kept a green "status 0: normal" through the outage. Stale values are
  // greyed under "last seen ... ago" and a lamp is only a ring.
  EXPECT_GT(before.sidebar_green, 150) << "no green in the panels while the lidar scans";
  EXPECT_LT(dead.sidebar_green, before.sidebar_green / 4)
      << "the panels still say all is well in green while no data comes (" << dead.sidebar_green << " green pixels, "
      << before.sidebar_green << " while live)";

  // The same port comes back and the app reconnects by itself.
  sim = spawn_in(dir, sim_argv);
  const bool back = wait_for_path(link, std::chrono::seconds(15));
  EXPECT_TRUE(back) << "the virtual lidar did not come back at " << link;
  const NoDataReading after =
      back ? screenshot_until(app, dir, seen, read, live, std::chrono::seconds(40)) : NoDataReading{};
  EXPECT_GT(after.points, 300) << "the scan did not come back after the lidar returned";
  EXPECT_LT(after.overlay_words, 400) << "the overlay stayed after the lidar returned";

  EXPECT_EQ(stop_process(app, SIGTERM), 0);
  stop_process(sim, SIGTERM);
  // Kept when something failed (or when asked), to look at.
  if (!HasFailure() && !std::getenv("YDSCOPE_KEEP_TEST_PNGS")) std::filesystem::remove_all(dir);
}

#endif

}  // namespace
}  // namespace ydscope::test
