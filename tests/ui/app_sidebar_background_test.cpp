// The sidebar's background is cleared by the app with GL rather than drawn by ImGui (a blended
// rectangle that size cost about 3 ms of CPU a frame on llvmpipe; docs/performance.md): it must
// still fill the sidebar from top to bottom in the colour ImGui gave it (the theme's window colour
// at 94 % over the view's background), and stop where the view begins. Under an Xvfb of 1280x800.
#include <gtest/gtest.h>

#include <cstdlib>

#include "app_test_support.h"

namespace ydscope::test {
namespace {

#ifdef YDSCOPE_APP_PATH

// The sidebar's colour as ImGui blended it (18, 21, 26 on llvmpipe), within a step of rounding.
bool sidebar_pixel(const unsigned char* p) {
  return std::abs(p[0] - 18) <= 1 && std::abs(p[1] - 21) <= 1 && std::abs(p[2] - 26) <= 1;
}
// The view's background, kBackground (9, 11, 15).
bool view_background_pixel(const unsigned char* p) {
  return std::abs(p[0] - 9) <= 1 && std::abs(p[1] - 11) <= 1 && std::abs(p[2] - 15) <= 1;
}

TEST(AppSidebarBackground, FillsTheSidebarInItsColourAndStopsAtTheView) {
  if (std::system("command -v xvfb-run >/dev/null 2>&1") != 0) GTEST_SKIP() << "xvfb-run is not installed";
  const std::filesystem::path dir = fresh_temp_dir("ydscope-sidebar-background");
  const std::string png = (dir / "window.png").string();
  const std::string command = "cd '" + dir.string() + "' && XDG_CONFIG_HOME='" + dir.string() +
                              "' xvfb-run -a -s '-screen 0 1280x800x24' '" + YDSCOPE_APP_PATH +
                              "' --sim G6 --screenshot '" + png + "' --frames 30 > /dev/null";
  ASSERT_EQ(std::system(command.c_str()), 0) << command;
  const Image image = load_png(png);
  ASSERT_TRUE(image) << png;

  // The sidebar's left margin, where no widget draws, top to bottom.
  const int rows = image.height - 20;
  EXPECT_EQ(count_pixels(image, {2, 10, 5, 10 + rows}, sidebar_pixel), 3 * rows)
      << "the sidebar's margin is not the sidebar's colour all the way down";
  // Its top margin, above the tabs, from the left edge to where the view's own background begins.
  int edge = -1;
  for (int x = 200; x < kViewLeft + 40 && edge < 0; ++x)
    if (view_background_pixel(image.at(x, 3))) edge = x;
  ASSERT_GT(edge, 300) << "no view background within " << kViewLeft + 40 << " px of the window's left";
  EXPECT_EQ(count_pixels(image, {2, 2, edge - 1, 6}, sidebar_pixel), 4 * (edge - 3))
      << "the sidebar's colour does not run to its right edge (the view begins at x=" << edge << ")";
  if (!HasFailure() && !std::getenv("YDSCOPE_KEEP_TEST_PNGS")) std::filesystem::remove_all(dir);
}

#endif

}  // namespace
}  // namespace ydscope::test
