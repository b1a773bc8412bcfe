// Identity by serial in the window, under an Xvfb of the test's own: two virtual lidars with
// different serials, named the wrong way round for their ports but bound by --serial. Once both
// answer, each name and pose sits on the port its unit is on, and settings.ini, written at exit,
// binds each name to its unit's serial and starts each from the port it was really on.
#include <gtest/gtest.h>

#include <fstream>
#include <iterator>
#include <optional>

#include "app_test_support.h"
#include "private_display.h"

namespace ydscope::test {
namespace {

#ifdef YDSCOPE_APP_PATH

constexpr const char* kFrontSerial = "1111222233334444";
constexpr const char* kRearSerial = "5555666677778888";

TEST(AppIdentity, NamesAndPosesFollowTheUnitsSerialsAcrossSwappedPorts) {
  if (std::system("command -v Xvfb >/dev/null 2>&1") != 0) GTEST_SKIP() << "Xvfb is not installed";
  PrivateDisplay display;
  ASSERT_TRUE(display) << "could not start an Xvfb of the test's own";
  const std::filesystem::path dir = fresh_temp_dir("ydscope-AppIdentity");
  const std::string a = (dir / "a").string(), b = (dir / "b").string();
  struct Running {
    std::vector<pid_t> pids;
    ~Running() {
      for (const pid_t pid : pids) stop_process(pid, SIGKILL);
    }
  } running;
  // Front's unit is on a, rear's on b.
  running.pids.push_back(
      spawn_in(dir, {YDSCOPE_CLI_PATH, "sim", "--model", "G6", "--pty", a, "--serial", kFrontSerial}));
  running.pids.push_back(
      spawn_in(dir, {YDSCOPE_CLI_PATH, "sim", "--model", "G6", "--pty", b, "--serial", kRearSerial}));
  ASSERT_TRUE(wait_for_path(a, std::chrono::seconds(15)) && wait_for_path(b, std::chrono::seconds(15)));
  const pid_t app =
      spawn_in(dir, {YDSCOPE_APP_PATH, "--model", "G6", "--port", a, "--name", "rear", "--serial", kRearSerial,
                     "--pose", "0,-2,0", "--port", b, "--name", "front", "--serial", kFrontSerial, "--pose", "0,2,0"});
  running.pids.push_back(app);
  // Both clouds drawn: both units have answered A5 90, so the names have followed them.
  std::set<std::string> seen;
  const int points = screenshot_until(
      app, dir, seen, [](const Image& image) { return points_in_rings(image, 448); }, [](int n) { return n > 3000; },
      std::chrono::seconds(30));
  ASSERT_GT(points, 3000) << "the two clouds never showed";
  running.pids.pop_back();
  ASSERT_EQ(stop_process(app, SIGTERM), 0) << "the app did not end cleanly on SIGTERM";

  std::ifstream file(dir / "ydscope" / "settings.ini");
  const std::string settings(std::istreambuf_iterator<char>(file), {});
  EXPECT_NE(settings.find("unit = " + std::string(kFrontSerial) + "; front\n"), std::string::npos) << settings;
  EXPECT_NE(settings.find("unit = " + std::string(kRearSerial) + "; rear\n"), std::string::npos) << settings;
  // Each keeps its pose, and is started next time from the port its unit was on.
  EXPECT_NE(settings.find("source = front; 0,2,0; #"), std::string::npos) << settings;
  EXPECT_NE(settings.find("; port G6 " + a + "\n"), std::string::npos) << settings;
  const std::size_t front_line = settings.find("source = front;");
  ASSERT_NE(front_line, std::string::npos) << settings;
  EXPECT_EQ(settings.substr(front_line, settings.find('\n', front_line) - front_line).find(b), std::string::npos)
      << "front is remembered on rear's port b:\n"
      << settings;
  std::filesystem::remove_all(dir);
}

#endif

}  // namespace
}  // namespace ydscope::test
