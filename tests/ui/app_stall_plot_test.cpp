// A stalling lidar under Xvfb, as a person looks at it: the Statistics tab's per-lap plots mark
// each interruption with a red tick instead of drawing the line straight across it as a slow motor
// (issue 26).
#include <gtest/gtest.h>

#include <cstdlib>

#include "app_test_support.h"
#include "hands_on_app.h"

namespace ydscope::test {
namespace {

#ifdef YDSCOPE_APP_PATH

// The plots panel's interruption tick (ui/panels/plots_panel.cpp: 255, 90, 80), in the sidebar.
bool is_tick_red(const unsigned char* p) { return p[0] > 220 && p[1] > 60 && p[1] < 120 && p[2] > 50 && p[2] < 110; }

int red_ticks_in_sidebar(const Image& image) { return count_pixels(image, {0, 60, 420, image.height}, is_tick_red); }

class AppStallPlot : public HandsOnApp {};

TEST_F(AppStallPlot, EachStallIsMarkedOnThePlots) {
  X11Hands& hands = this->hands();
  const std::filesystem::path dir = fresh_temp_dir("ydscope-stall-plot");
  const std::string link = (dir / "lidar").string();
  // A 700 ms stall every 2.5 s: long enough to cut a lap, short of the 2 s that reconnects.
  const pid_t sim = spawn_in(
      dir, {YDSCOPE_CLI_PATH, "sim", "--model", "G6", "--pty", link, "--stall-ms", "700", "--stall-every-ms", "2500"});
  ASSERT_TRUE(wait_for_path(link, std::chrono::seconds(15))) << "the virtual lidar did not make " << link;
  const pid_t app = spawn_in(dir, {YDSCOPE_APP_PATH, "--port", link, "--model", "G6"});
  ASSERT_TRUE(hands.find_window("ydscope", std::chrono::seconds(30))) << "no ydscope window appeared";
  std::set<std::string> seen;
  // The Statistics tab, second from the left of the sidebar's tab row (its text starts at x 135).
  const auto open_statistics = [&] {
    hands.move_pointer(160, 21);
    hands.left_button(true, 160, 21);
    hands.left_button(false, 160, 21);
  };
  open_statistics();
  const auto marked = [](int red) { return red > 40; };
  int red = 0;
  for (const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(40);
       std::chrono::steady_clock::now() < deadline && !marked(red);) {
    const Image image = screenshot_of(app, dir, seen);
    if (!image) continue;
    red = red_ticks_in_sidebar(image);
    if (!marked(red)) open_statistics();  // a click before the window took input is lost
  }
  EXPECT_TRUE(marked(red)) << "no red interruption tick on the Statistics tab's plots after the stalls (" << red
                           << " red pixels)";

  EXPECT_EQ(stop_process(app, SIGTERM), 0);
  stop_process(sim, SIGTERM);
  if (!HasFailure() && !std::getenv("YDSCOPE_KEEP_TEST_PNGS")) std::filesystem::remove_all(dir);
}

#endif

}  // namespace
}  // namespace ydscope::test
