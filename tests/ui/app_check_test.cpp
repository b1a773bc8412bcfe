// The app's Run check (Lidar tab) on a virtual lidar under Xvfb: the same acceptance check as
// `ydscope-cli check` runs on the selected lidar, its verdict shows in the Lidar tab in the
// report's colours, the report is written under the unit's serial and handed to xdg-open, and the
// lidar comes back to the view afterwards.
#include <gtest/gtest.h>

#include <cstdlib>
#include <fstream>

#include "app_test_support.h"
#include "hands_on_app.h"
#include "support/text_file.h"

namespace ydscope::test {
namespace {

using test::read_text;

#ifdef YDSCOPE_APP_PATH

// The Check panel's PASS badge (ui/panels/check_panel.cpp: 0.18, 0.49, 0.20).
bool is_pass_green(const unsigned char* p) {
  return std::abs(p[0] - 46) < 8 && std::abs(p[1] - 125) < 8 && std::abs(p[2] - 51) < 8;
}

class AppCheck : public HandsOnApp {};

TEST_F(AppCheck, RunCheckShowsTheVerdictAndOpensTheReport) {
  X11Hands& hands = this->hands();
  const std::filesystem::path dir = fresh_temp_dir("ydscope-app-check");
  const std::string link = (dir / "lidar").string();
  // A stand-in xdg-open first on PATH: it notes what it was asked to open.
  const std::filesystem::path bin = dir / "bin";
  std::filesystem::create_directories(bin);
  {
    std::ofstream script(bin / "xdg-open");
    script << "#!/bin/sh\nprintf '%s\\n' \"$1\" >> '" << (dir / "opened.txt").string() << "'\n";
  }
  std::filesystem::permissions(bin / "xdg-open", std::filesystem::perms::owner_all);
  const std::string path = bin.string() + ":" + (std::getenv("PATH") ? std::getenv("PATH") : "/usr/bin:/bin");
  setenv("PATH", path.c_str(), 1);  // the app inherits it; this test runs in a process of its own

  const pid_t sim = spawn_in(dir, {YDSCOPE_CLI_PATH, "sim", "--model", "G6", "--scene", "room", "--pty", link});
  ASSERT_TRUE(wait_for_path(link, std::chrono::seconds(15))) << "the virtual lidar did not make " << link;
  // --check presses Run check once the app has started: the request the button sends.
  const pid_t app = spawn_in(dir, {YDSCOPE_APP_PATH, "--port", link, "--model", "G6", "--check"});
  ASSERT_TRUE(hands.find_window("ydscope", std::chrono::seconds(30))) << "no ydscope window appeared";

  // The report appears once the run (1 s settling, 10 s measuring) is over.
  std::filesystem::path report;
  for (const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(90);
       report.empty() && std::chrono::steady_clock::now() < deadline;) {
    for (const auto& entry : std::filesystem::directory_iterator(dir))
      if (entry.path().extension() == ".html") report = entry.path();
    std::this_thread::sleep_for(std::chrono::milliseconds(200));
  }
  ASSERT_FALSE(report.empty()) << "no report was written into " << dir;
  const std::string html = read_text(report);
  EXPECT_NE(html.find(R"(id="verdict">PASS</span>)"), std::string::npos) << report;
  EXPECT_NE(html.find("ydscope-cli check --port " + link), std::string::npos) << "the command line it stands for";
  // Named as a station names it: the serial, then the time.
  EXPECT_NE(report.filename().string().find('-'), std::string::npos) << report;
  EXPECT_TRUE(wait_for_path(dir / "opened.txt", std::chrono::seconds(10)));
  EXPECT_EQ(read_text(dir / "opened.txt"), report.string() + "\n") << "the report handed to xdg-open";

  // The verdict in the Lidar tab: the green PASS badge in the sidebar.
  std::set<std::string> seen;
  int green = 0;
  for (const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(20);
       green < 200 && std::chrono::steady_clock::now() < deadline;) {
    const Image image = screenshot_of(app, dir, seen);
    if (image) green = count_pixels(image, {0, 0, 420, image.height}, is_pass_green);
  }
  EXPECT_GE(green, 200) << "no PASS badge in the Lidar tab (" << green << " badge-green pixels)";
  // And the lidar is back in the view: the session took its port back after the check.
  int points = 0;
  for (const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(20);
       points <= 300 && std::chrono::steady_clock::now() < deadline;) {
    const Image image = screenshot_of(app, dir, seen);
    if (image) points = points_in_rings(image, 448);  // the view is right of the panels
  }
  EXPECT_GT(points, 300) << "the scan did not come back after the check";

  EXPECT_EQ(stop_process(app, SIGTERM), 0);
  stop_process(sim, SIGTERM);
  if (!HasFailure() && !std::getenv("YDSCOPE_KEEP_TEST_PNGS")) std::filesystem::remove_all(dir);
}

#endif

}  // namespace
}  // namespace ydscope::test
