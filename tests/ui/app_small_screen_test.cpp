// On a 1024x600 screen the first window fits: the whole window is on the screen, the status line
// is drawn at the bottom of the view, and the lidar sits in the middle of the view, not at an
// edge. The test starts its own Xvfb of that size (the suite's display is 1280x800).
#include <gtest/gtest.h>

#include <cstdlib>

#include "app_test_support.h"

namespace ydscope::test {
namespace {

#ifdef YDSCOPE_APP_PATH

// The status line's words in the "ok" green of a scanning link.
bool ok_green(const unsigned char* p) { return p[1] > 200 && p[0] > 80 && p[0] < 150 && p[2] > 110 && p[2] < 190; }

TEST(AppSmallScreen, TheFirstWindowFitsA1024x600Screen) {
  if (std::system("command -v xvfb-run >/dev/null 2>&1") != 0) GTEST_SKIP() << "xvfb-run is not installed";
  const std::filesystem::path dir = fresh_temp_dir("ydscope-small-screen");
  const std::string png = (dir / "small.png").string();
  const std::string command = "cd '" + dir.string() + "' && XDG_CONFIG_HOME='" + dir.string() +
                              "' xvfb-run -a -s '-screen 0 1024x600x24' '" + YDSCOPE_APP_PATH +
                              "' --sim G6 --screenshot '" + png + "' --frames 60 > /dev/null";
  ASSERT_EQ(std::system(command.c_str()), 0) << command;
  const Image image = load_png(png);
  ASSERT_TRUE(image) << png;
  EXPECT_LE(image.width, 1024) << "the window is wider than the screen";
  EXPECT_LE(image.height, 600) << "the window is taller than the screen";
  EXPECT_GE(image.width, 1000) << "the window does not use the screen's width";
  EXPECT_GE(image.height, 520) << "the window does not use the screen's height";

  // The view is right of the sidebar, which takes at most 40 % of the width.
  const int view_left = image.width * 2 / 5;
  const int status = count_pixels(image, {view_left, image.height - 40, image.width, image.height}, ok_green);
  EXPECT_GT(status, 150) << "no status line in the bottom 40 px of the view";

  // The lidar's white dot and heading chevron: the only near-white pixels in the middle band.
  long sum_x = 0, sum_y = 0, n = 0;
  for (int y = image.height / 4; y < image.height * 3 / 4; ++y)
    for (int x = view_left; x < image.width; ++x)
      if (is_white_pixel(image.at(x, y))) {
        sum_x += x;
        sum_y += y;
        ++n;
      }
  ASSERT_GT(n, 20) << "the lidar's marker is not in the middle band of the view";
  const int lidar_x = static_cast<int>(sum_x / n), lidar_y = static_cast<int>(sum_y / n);
  const int view_centre = (view_left + image.width) / 2;
  EXPECT_NEAR(lidar_x, view_centre, (image.width - view_left) / 8) << "the lidar is not in the middle of the view";
  EXPECT_GT(image.width - lidar_x, 200) << "the lidar is at the right edge";
  EXPECT_NEAR(lidar_y, image.height / 2, image.height / 8);
  if (!HasFailure() && !std::getenv("YDSCOPE_KEEP_TEST_PNGS")) std::filesystem::remove_all(dir);
}

#endif

}  // namespace
}  // namespace ydscope::test
