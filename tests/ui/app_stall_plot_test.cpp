// A stalling lidar under Xvfb, as a person looks at it: the Statistics tab's plots mark each
// interruption with a red tick instead of drawing the line straight across it as a slow motor
// (issue 26), at its time on the plots' shared time axis (issue 30).
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdlib>
#include <vector>

#include "app_test_support.h"
#include "hands_on_app.h"

namespace ydscope::test {
namespace {

#ifdef YDSCOPE_APP_PATH

// The plots' stall mark (ui/panels/time_plot.cpp: 255, 90, 80), in the sidebar.
bool is_tick_red(const unsigned char* p) { return p[0] > 220 && p[1] > 60 && p[1] < 120 && p[2] > 50 && p[2] < 110; }

int red_ticks_in_sidebar(const Image& image) { return count_pixels(image, {0, 60, 420, image.height}, is_tick_red); }

// The x of each column of stall marks that runs down at least four of the plots (each mark's
// first pixel column): one stall, marked at one time on the time axis the plots share.
std::vector<int> stall_columns(const Image& image) {
  std::vector<int> columns;
  for (int x = 0; x < 420; ++x) {
    int rows = 0, plots = 0;
    bool in_mark = false;
    for (int y = 60; y < image.height; ++y) {
      const bool red = is_tick_red(image.at(x, y));
      rows += red ? 1 : 0;
      if (red && !in_mark) ++plots;
      in_mark = red;
    }
    if (plots >= 4 && rows >= 100 && (columns.empty() || x > columns.back() + 3)) columns.push_back(x);
  }
  return columns;
}

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
  // Issue 30: the plots share one time axis, so a stall is marked at its time on every plot, the
  // marks one above the other in a column; and the stalls, 2.5 s apart, are as far apart on it.
  std::vector<int> columns;
  for (const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(40);
       std::chrono::steady_clock::now() < deadline && columns.size() < 3;) {
    if (const Image image = screenshot_of(app, dir, seen)) columns = stall_columns(image);
  }
  EXPECT_GE(columns.size(), 3u) << "fewer than three stalls marked in a column across the plots";
  std::vector<int> gaps;
  for (std::size_t i = 1; i < columns.size(); ++i) gaps.push_back(columns[i] - columns[i - 1]);
  std::sort(gaps.begin(), gaps.end());
  // A stall is stamped with the frame that measured its lap: within a frame (up to 0.2 s on this
  // loaded machine) of its time, a twelfth of the period either way.
  for (const int gap : gaps)
    EXPECT_NEAR(gap, gaps[gaps.size() / 2], std::max(5, gaps[gaps.size() / 2] / 3))
        << "the stalls, 2.5 s apart, are not evenly spaced in time: marks at x " << testing::PrintToString(columns);

  EXPECT_EQ(stop_process(app, SIGTERM), 0);
  stop_process(sim, SIGTERM);
  if (!HasFailure() && !std::getenv("YDSCOPE_KEEP_TEST_PNGS")) std::filesystem::remove_all(dir);
}

#endif

}  // namespace
}  // namespace ydscope::test
