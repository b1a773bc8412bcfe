// The booth view (--fullscreen) on a 1920x1080 screen: the model is written in large type,
// legible across a stand, and a colour legend (a range bar from blue to red with ticks in metres)
// says what the colours mean. The test starts its own Xvfb of that size.
#include <gtest/gtest.h>

#include <cstdlib>

#include "app_test_support.h"

namespace ydscope::test {
namespace {

#ifdef YDSCOPE_APP_PATH

// The longest run of saturated pixels along one row of `r` that goes from blue to red.
int longest_blue_to_red_run(const Image& image, Rect r) {
  int best = 0;
  for (int y = r.y0; y < r.y1; ++y) {
    int start = -1;
    for (int x = r.x0; x <= r.x1; ++x) {
      const bool on = x < r.x1 && is_point_pixel(image.at(x, y));
      if (on && start < 0) start = x;
      if (!on && start >= 0) {
        const int length = x - start;
        const unsigned char* first = image.at(start + 2, y);
        const unsigned char* last = image.at(x - 3, y);
        if (length > best && first[2] > first[0] && last[0] > last[2]) best = length;
        start = -1;
      }
    }
  }
  return best;
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

TEST(AppBoothView, LargeTypeAndAColourLegendAt1080p) {
  if (std::system("command -v xvfb-run >/dev/null 2>&1") != 0) GTEST_SKIP() << "xvfb-run is not installed";
  const std::filesystem::path dir = fresh_temp_dir("ydscope-booth");
  const std::string png = (dir / "booth.png").string();
  const std::string command = "cd '" + dir.string() + "' && XDG_CONFIG_HOME='" + dir.string() +
                              "' xvfb-run -a -s '-screen 0 1920x1080x24' '" + YDSCOPE_APP_PATH +
                              "' --sim G6 --fullscreen --screenshot '" + png + "' --frames 60 > /dev/null";
  ASSERT_EQ(std::system(command.c_str()), 0) << command;
  const Image image = load_png(png);
  ASSERT_TRUE(image) << png;
  ASSERT_EQ(image.width, 1920) << "not full screen";
  ASSERT_EQ(image.height, 1080) << "not full screen";

  // The legend's bar: a long unbroken band from blue to red in the bottom-right corner (scan
  // points never make a straight run that long, nor one ordered by colour).
  const int run = longest_blue_to_red_run(image, {image.width / 2, image.height * 2 / 3, image.width, image.height});
  EXPECT_GT(run, 250) << "no colour legend bar in the bottom-right corner";

  // The model, top left, in type several times the panels' 16 px: its first line of glyphs is
  // taller than 16 px text could be.
  const int line = first_text_line_height(image, {0, 0, image.width / 5, image.height / 6});
  EXPECT_GE(line, 26) << "the booth view's type is not large";
  if (!HasFailure() && !std::getenv("YDSCOPE_KEEP_TEST_PNGS")) std::filesystem::remove_all(dir);
}

#endif

}  // namespace
}  // namespace ydscope::test
