// The booth view (--fullscreen) on a 1920x1080 screen: the model is written in large type,
// legible across a stand; motion highlighting is on, so on the virtual booth scene the visitors
// walking along the aisle ahead are hot and the stand's own walls behind the lidar calm; and a
// legend in the bottom-right corner names both colours; the view frames the scene, not its farthest corner. (The range
// legend's bar and ticks are checked without a display, tests/ui/colour_legend_test.cpp.) The test
// starts its own Xvfb of that size.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdlib>

#include "app_test_support.h"

namespace ydscope::test {
namespace {

#ifdef YDSCOPE_APP_PATH

// Motion mode's colours (ui/view/scene/colour_map.cpp motion_colour), with some room for blending.
bool hot(const unsigned char* p) { return p[0] > 210 && p[1] > 60 && p[1] < 140 && p[2] < 100; }
bool calm(const unsigned char* p) {
  return std::abs(p[0] - 88) < 30 && std::abs(p[1] - 128) < 30 && std::abs(p[2] - 170) < 30;
}

// Height of the first block of rows holding text-white pixels in `r`: the first line's glyphs.
int first_text_line_height(const Image& image, Rect r) {
  int top = -1;
  for (int y = r.y0; y < r.y1; ++y) {
    const bool ink = count_pixels(image, {r.x0, y, r.x1, y + 1}, is_white_pixel) >= 2;
    if (ink && top < 0) top = y;
    if (!ink && top >= 0) return y - top;
  }
  return 0;
}

TEST(AppBoothView, LargeTypeMotionColoursAndTheirLegendAt1080p) {
  if (std::system("command -v xvfb-run >/dev/null 2>&1") != 0) GTEST_SKIP() << "xvfb-run is not installed";
  const std::filesystem::path dir = fresh_temp_dir("ydscope-booth");
  const std::string png = (dir / "booth.png").string();
  // 150 frames: some 40 laps, enough for the room to be learned (MotionBackground).
  const std::string command =
      "cd '" + dir.string() + "' && XDG_CONFIG_HOME='" + dir.string() + "' xvfb-run -a -s '-screen 0 1920x1080x24' '" +
      YDSCOPE_APP_PATH + "' --sim G6 --scene booth --fullscreen --screenshot '" + png + "' --frames 150 > /dev/null";
  ASSERT_EQ(std::system(command.c_str()), 0) << command;
  const Image image = load_png(png);
  ASSERT_TRUE(image) << png;
  ASSERT_EQ(image.width, 1920) << "not full screen";
  ASSERT_EQ(image.height, 1080) << "not full screen";

  // Towards the unit's 0 (drawn down: the laser frame's -x, as ROS tools draw it) the aisle:
  // visitors walking past, hot. Towards its 180 (the upper half, clear of the model's name at the
  // left) the stand's walls and kiosk: calm, none hot.
  const int cy = image.height / 2;
  const Rect aisle{image.width / 4, cy + 20, image.width * 3 / 4, image.height * 7 / 8};
  const Rect stand{image.width / 4, image.height / 8, image.width * 3 / 4, cy - 20};
  EXPECT_GT(count_pixels(image, aisle, hot), 150) << "no visitor in the aisle is painted as moving";
  EXPECT_GT(count_pixels(image, stand, calm), 300) << "the stand's walls are not the calm colour";
  EXPECT_LT(count_pixels(image, stand, hot), 20) << "the stand's static walls are painted as moving";

  // The legend: both colours' swatches in the bottom-right corner, with words beside them.
  const Rect corner{image.width * 3 / 4, image.height * 3 / 4, image.width, image.height};
  EXPECT_GT(count_pixels(image, corner, hot), 80) << "no 'moving' swatch in the legend";
  EXPECT_GT(count_pixels(image, corner, calm), 80) << "no 'room' swatch in the legend";
  EXPECT_GT(count_pixels(image, corner, is_text_pixel), 300) << "no legend words";

  // The view frames the scene it sees (issue 30): the hall's end walls reach near the screen's left
  // edge (and right) and the opposite stands' wall near its bottom, rather than the scene sitting
  // small inside rings sized for its farthest corner. (Left of the legend, under the model's name.)
  int left = image.width, lowest = 0;
  for (int y = image.height / 6; y < image.height * 15 / 16; ++y)
    for (int x = 0; x < image.width * 3 / 4; ++x)
      if (calm(image.at(x, y))) left = std::min(left, x), lowest = std::max(lowest, y);
  EXPECT_LT(left, image.width / 6) << "the scene does not reach the screen's left sixth";
  EXPECT_GT(lowest, image.height * 4 / 5) << "the opposite stands' wall is not near the bottom";

  // The model, top left, in type several times the panels' 16 px: its first line of glyphs is
  // taller than 16 px text could be.
  const int line = first_text_line_height(image, {0, 0, image.width / 5, image.height / 6});
  EXPECT_GE(line, 26) << "the booth view's type is not large";
  if (!HasFailure() && !std::getenv("YDSCOPE_KEEP_TEST_PNGS")) std::filesystem::remove_all(dir);
}

#endif

}  // namespace
}  // namespace ydscope::test
