// The real app under the display CTest provides (scripts/test wraps ctest in xvfb-run): render
// frames with laps arriving, write a screenshot, exit 0; the PNG must show points and panels.
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <string>

#include "app_test_support.h"
#include "test_data.h"

namespace {

using namespace ydscope::test;

#ifdef YDSCOPE_APP_PATH

int run_app(const std::string& arguments) {
  const std::filesystem::path home = std::filesystem::path(testing::TempDir()) / "ydscope-ui-home";
  std::filesystem::create_directories(home);
  const std::string command = "XDG_CONFIG_HOME='" + home.string() + "' '" + YDSCOPE_APP_PATH + "' " + arguments;
  const int status = std::system(command.c_str());
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

void expect_scan_and_panels(const std::string& png) {
  const Image image = load_png(png);
  ASSERT_TRUE(image.pixels) << "the app did not write a readable PNG at " << png;
  ASSERT_GE(image.width, 640);
  ASSERT_GE(image.height, 400);
  // Panels: the sidebar takes the left third and holds light text.
  int text = 0;
  for (int y = 0; y < image.height; ++y)
    for (int x = 0; x < image.width / 3; ++x) text += is_text_pixel(image.at(x, y));
  EXPECT_GT(text, 500) << "no panel text in the left third";
  // Points: bright coloured pixels in the view, within the rings around its centre.
  const int view_left = image.width * 35 / 100;
  const int points = points_in_rings(image, view_left);
  const int far_background = count_pixels(image, {view_left, 0, image.width, image.height},
                                          [](const unsigned char* p) { return p[0] < 40 && p[1] < 40 && p[2] < 50; });
  EXPECT_GT(points, 300) << "no lidar points drawn inside the rings";
  EXPECT_GT(far_background, (image.width - view_left) * image.height / 3) << "the view is not the dark background";
}

TEST(AppSmoke, VirtualG6RendersAScreenshot) {
  if (!std::getenv("DISPLAY")) GTEST_SKIP() << "no DISPLAY: run under xvfb-run (scripts/test does)";
  const std::string png = std::string(testing::TempDir()) + "ydscope-smoke-sim.png";
  std::filesystem::remove(png);
  ASSERT_EQ(run_app("--sim G6 --screenshot '" + png + "' --frames 120"), 0);
  expect_scan_and_panels(png);
}

// --sector 260:280 shades a wedge on the lidar's right (270 degrees: the laser frame's -y, drawn to
// the right as ROS tools draw it): a dim orange tint between the lidar and the wall there, and none
// in the mirror image on its left.
TEST(AppSmoke, AWatchedSectorIsShadedOnTheView) {
  if (!std::getenv("DISPLAY")) GTEST_SKIP() << "no DISPLAY: run under xvfb-run (scripts/test does)";
  const std::string png = std::string(testing::TempDir()) + "ydscope-smoke-sector.png";
  std::filesystem::remove(png);
  ASSERT_EQ(run_app("--sim G6 --scene room --sector 260:280 --screenshot '" + png + "' --frames 90"), 0);
  const Image image = load_png(png);
  ASSERT_TRUE(image.pixels) << png;
  const int view_left = image.width * 35 / 100;
  const int cx = (view_left + image.width) / 2, cy = image.height / 2;
  const auto tinted = [](const unsigned char* p) { return p[0] > p[2] + 12 && p[0] < 120 && p[1] < 100; };
  const int left = count_pixels(image, {cx - 160, cy - 8, cx - 40, cy + 8}, tinted);
  const int right = count_pixels(image, {cx + 40, cy - 8, cx + 160, cy + 8}, tinted);
  EXPECT_GT(right, 120 * 16 / 2) << "no sector shading right of the lidar";
  EXPECT_LT(left, 120 * 16 / 20) << "shading where no sector is";
}

// The unit's 0 and sweep are marked at the lidar (pale steel): a lone lidar is drawn in its laser
// frame, so the tick to its 0 points straight down, none points up, and the sweep's arrow runs
// from there round to the lidar's left (clockwise on screen).
TEST(AppSmoke, TheUnitsZeroAndSweepAreMarkedAtTheLidar) {
  if (!std::getenv("DISPLAY")) GTEST_SKIP() << "no DISPLAY: run under xvfb-run (scripts/test does)";
  const std::string png = std::string(testing::TempDir()) + "ydscope-smoke-unit-marks.png";
  std::filesystem::remove(png);
  ASSERT_EQ(run_app("--sim G6 --scene room --screenshot '" + png + "' --frames 60"), 0);
  const Image image = load_png(png);
  ASSERT_TRUE(image.pixels) << png;
  const int view_left = image.width * 35 / 100;
  const int cx = (view_left + image.width) / 2, cy = image.height / 2;
  // The marks' pale steel (190, 200, 228): bluish grey, brighter than the grid, greyer than any return.
  const auto mark = [](const unsigned char* p) {
    return p[0] > 160 && p[0] < 215 && p[1] > 170 && p[1] < 225 && p[2] > 205 && p[2] - p[0] > 15 && p[2] - p[0] < 60;
  };
  // The lidar sits near the view's centre (the sidebar's width varies by a few pixels): search
  // its column, then look round it.
  int lidar_x = cx, best = 0;
  for (int x = cx - 30; x <= cx + 30; ++x) {
    const int n = count_pixels(image, {x - 1, cy + 12, x + 2, cy + 31}, mark);
    if (n > best) best = n, lidar_x = x;
  }
  const int below = count_pixels(image, {lidar_x - 2, cy + 12, lidar_x + 3, cy + 31}, mark);
  const int above = count_pixels(image, {lidar_x - 5, cy - 31, lidar_x + 6, cy - 12}, mark);
  const int sweep_left = count_pixels(image, {lidar_x - 30, cy - 8, lidar_x - 8, cy + 26}, mark);
  const int sweep_right = count_pixels(image, {lidar_x + 8, cy - 8, lidar_x + 30, cy + 26}, mark);
  EXPECT_GT(below, 12) << "no tick to the unit's 0 below the lidar";
  EXPECT_LT(above, 3) << "a tick above the lidar: the 0 is drawn the wrong way";
  EXPECT_GT(sweep_left, 15) << "no sweep arrow on the lidar's left";
  EXPECT_LT(sweep_right, 3) << "the sweep arrow runs the wrong way";
}

TEST(AppSmoke, DemoRecordingReplaysIntoAScreenshot) {
  if (!std::getenv("DISPLAY")) GTEST_SKIP() << "no DISPLAY: run under xvfb-run (scripts/test does)";
  const std::string recording = (ydscope::test::assets_dir() / "demo-g6.ydrec").string();
  ASSERT_TRUE(std::filesystem::exists(recording)) << recording;
  EXPECT_LT(std::filesystem::file_size(recording), 1'000'000u) << "keep the committed demo recording small";
  const std::string png = std::string(testing::TempDir()) + "ydscope-smoke-replay.png";
  std::filesystem::remove(png);
  ASSERT_EQ(run_app("--replay '" + recording + "' --screenshot '" + png + "' --frames 60"), 0);
  expect_scan_and_panels(png);
}

TEST(AppSmoke, MissingRecordingFailsWithASentence) {
  if (!std::getenv("DISPLAY")) GTEST_SKIP() << "no DISPLAY: run under xvfb-run (scripts/test does)";
  const std::string png = std::string(testing::TempDir()) + "ydscope-smoke-missing.png";
  EXPECT_EQ(run_app("--replay /nonexistent/none.ydrec --screenshot '" + png + "' 2>/dev/null"), 1);
}

TEST(AppSmoke, SigtermEndsTheLoopAndSavesSettings) {
  if (!std::getenv("DISPLAY")) GTEST_SKIP() << "no DISPLAY: run under xvfb-run (scripts/test does)";
  const std::filesystem::path home = std::filesystem::path(testing::TempDir()) / "ydscope-ui-persist";
  std::filesystem::remove_all(home);
  std::filesystem::create_directories(home);
  // The window runs interactively (no --screenshot) until SIGTERM, like a demo stopped by a service.
  const std::string command = "XDG_CONFIG_HOME='" + home.string() + "' timeout --preserve-status -s TERM 4 '" +
                              YDSCOPE_APP_PATH + "' --sim G1 --scene room";
  const int status = std::system(command.c_str());
  ASSERT_TRUE(WIFEXITED(status));
  EXPECT_EQ(WEXITSTATUS(status), 0) << "SIGTERM should end the loop normally";
  EXPECT_TRUE(std::filesystem::exists(home / "ydscope" / "settings.ini"));
  EXPECT_TRUE(std::filesystem::exists(home / "ydscope" / "imgui.ini"));
}

TEST(AppSmoke, BadOptionsExitWithUsageError) {
  EXPECT_EQ(run_app("--sim NOPE --screenshot x.png 2>/dev/null"), 2);
  EXPECT_EQ(run_app("--frames 3 2>/dev/null"), 2);
}

#endif

}  // namespace
