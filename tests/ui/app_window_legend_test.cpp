// The windowed view has a colour legend too (issue 30; the booth view always had one): in range
// colours, a bar running the palette from near (blue) to far (red) in the view's bottom-right
// corner, with its words. Taken as a user would see it, under an Xvfb of the usual 1280x800.
#include <gtest/gtest.h>

#include <cstdlib>

#include "app_test_support.h"

namespace ydscope::test {
namespace {

#ifdef YDSCOPE_APP_PATH

bool bluish(const unsigned char* p) { return p[2] > 150 && p[2] > p[0] + 60; }
bool reddish(const unsigned char* p) { return p[0] > 150 && p[0] > p[2] + 60 && p[1] < 140; }

// The longest run of saturated (palette) pixels on row `y` between x0 and x1: the legend's bar
// is one unbroken run; scan points are dots a few pixels wide.
std::pair<int, int> longest_run(const Image& image, int y, int x0, int x1) {
  int best_start = 0, best = 0, start = 0, run = 0;
  for (int x = x0; x < x1; ++x) {
    if (is_point_pixel(image.at(x, y))) {
      if (run++ == 0) start = x;
      if (run > best) best = run, best_start = start;
    } else {
      run = 0;
    }
  }
  return {best_start, best};
}

TEST(AppWindowLegend, TheRangeBarIsInTheViewsCorner) {
  if (std::system("command -v xvfb-run >/dev/null 2>&1") != 0) GTEST_SKIP() << "xvfb-run is not installed";
  const std::filesystem::path dir = fresh_temp_dir("ydscope-window-legend");
  const std::string png = (dir / "window.png").string();
  const std::string command = "cd '" + dir.string() + "' && XDG_CONFIG_HOME='" + dir.string() +
                              "' xvfb-run -a -s '-screen 0 1280x800x24' '" + YDSCOPE_APP_PATH +
                              "' --sim G6 --screenshot '" + png + "' --frames 60 > /dev/null";
  ASSERT_EQ(std::system(command.c_str()), 0) << command;
  const Image image = load_png(png);
  ASSERT_TRUE(image) << png;

  // The bottom-right fifth of the window, right of any sidebar: find the bar's row.
  const int x0 = image.width * 3 / 4, y0 = image.height * 3 / 4;
  int bar_y = -1, bar_x = 0, bar_w = 0;
  for (int y = y0; y < image.height; ++y) {
    const auto [start, length] = longest_run(image, y, x0, image.width);
    if (length > bar_w) bar_y = y, bar_x = start, bar_w = length;
  }
  ASSERT_GE(bar_w, 100) << "no legend bar (an unbroken run of palette colours) in the view's bottom-right corner";
  // Near is blue at its left end, far red at its right.
  EXPECT_TRUE(bluish(image.at(bar_x + 3, bar_y))) << "the bar does not start blue (near)";
  EXPECT_TRUE(reddish(image.at(bar_x + bar_w - 4, bar_y))) << "the bar does not end red (far)";
  // Its words ("range" and the ticks in metres) above and below it.
  EXPECT_GT(count_pixels(image, {bar_x - 10, bar_y - 40, bar_x + bar_w + 10, bar_y + 40}, is_text_pixel), 60)
      << "the legend has no words";
  if (!HasFailure() && !std::getenv("YDSCOPE_KEEP_TEST_PNGS")) std::filesystem::remove_all(dir);
}

#endif

}  // namespace
}  // namespace ydscope::test
