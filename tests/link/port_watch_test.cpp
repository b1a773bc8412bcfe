// PortWatch: the inotify wake-up that lets a reconnect try as soon as its serial port's path is
// back. Each test waits on a real io_context with a bound (a hang guard, not a time claim).
#include "core/link/port_watch.h"
#include "support/temp_dir.h"

#include <gtest/gtest.h>
#include <unistd.h>

#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <fstream>

namespace ydscope {
namespace {

namespace fs = std::filesystem;
using namespace std::chrono_literals;

class PortWatchTest : public ::testing::Test {
 protected:
  // Runs the io_context until the watch fired or `bound` passed; true when it fired.
  bool fired_within(std::chrono::milliseconds bound) {
    io_.restart();
    const auto deadline = std::chrono::steady_clock::now() + bound;
    while (!fired_ && std::chrono::steady_clock::now() < deadline) io_.run_for(20ms);
    return fired_;
  }
  bool arm(const fs::path& path) {
    return watch_.arm(path.string(), [this] { fired_ = true; });
  }

  test::TempDir dir_{"port-watch"};
  boost::asio::io_context io_;
  PortWatch watch_{io_};
  bool fired_ = false;
};

TEST_F(PortWatchTest, TargetIsTheNearestExistingDirectoryAndTheNameBelowIt) {
  const auto direct = PortWatch::target_for((dir_ / "ttyUSB0").string());
  EXPECT_EQ(direct.directory, dir_.string());
  EXPECT_EQ(direct.name, "ttyUSB0");
  // /dev/serial/by-id disappears with its last device: watch where it will be created again.
  const auto nested = PortWatch::target_for((dir_ / "serial" / "by-id" / "usb-Silicon_Labs-port0").string());
  EXPECT_EQ(nested.directory, dir_.string());
  EXPECT_EQ(nested.name, "serial");
}

TEST_F(PortWatchTest, ADeviceNodeCreatedUnderTheNameWakesTheWaiter) {
  ASSERT_TRUE(arm(dir_ / "ttyUSB0"));
  std::ofstream(dir_ / "ttyUSB0") << "";
  EXPECT_TRUE(fired_within(5s));
}

TEST_F(PortWatchTest, ASymlinkRenamedIntoPlaceWakesTheWaiter) {
  // The virtual lidar's --pty LINK and udev's by-id links are replaced this way.
  ASSERT_TRUE(arm(dir_ / "lidar"));
  fs::create_symlink("/dev/null", dir_ / "lidar.tmp");
  fs::rename(dir_ / "lidar.tmp", dir_ / "lidar");
  EXPECT_TRUE(fired_within(5s));
}

TEST_F(PortWatchTest, OtherEntriesOfTheDirectoryDoNotWakeIt) {
  ASSERT_TRUE(arm(dir_ / "ttyUSB0"));
  std::ofstream(dir_ / "ttyUSB1") << "";
  std::ofstream(dir_ / "ttyUSB00") << "";
  EXPECT_FALSE(fired_within(300ms));
  std::ofstream(dir_ / "ttyUSB0") << "";  // and it still waits for the right one
  EXPECT_TRUE(fired_within(5s));
}

TEST_F(PortWatchTest, AMissingParentDirectoryComingBackWakesIt) {
  ASSERT_TRUE(arm(dir_ / "by-id" / "usb-lidar"));
  fs::create_directory(dir_ / "by-id");
  EXPECT_TRUE(fired_within(5s));
}

TEST_F(PortWatchTest, DisarmedItNeverCallsBack) {
  ASSERT_TRUE(arm(dir_ / "ttyUSB0"));
  watch_.disarm();
  std::ofstream(dir_ / "ttyUSB0") << "";
  EXPECT_FALSE(fired_within(300ms));
}

}  // namespace
}  // namespace ydscope
