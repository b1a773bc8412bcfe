// ReconnectPlan: the waits between reopen attempts, and what is watched meanwhile.
#include "core/session/reconnect_plan.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include <unistd.h>

namespace ydscope {
namespace {

using namespace std::chrono_literals;

SessionConfig backoff_config(const std::string& address) {
  SessionConfig config;
  config.address = address;
  config.first_backoff = 250ms;
  config.max_backoff = 4000ms;
  return config;
}

std::vector<long> delays(ReconnectPlan& plan, int count) {
  std::vector<long> seen;
  for (int i = 0; i < count; ++i, plan.waited()) seen.push_back(static_cast<long>(plan.delay().count()));
  return seen;
}

TEST(ReconnectPlan, ASerialPortIsWatchedAndItsWaitDoublesUpToTheMaximum) {
  ReconnectPlan plan(backoff_config("/dev/ttyUSB0"));
  ASSERT_TRUE(plan.watched_path());
  EXPECT_EQ(*plan.watched_path(), "/dev/ttyUSB0");
  EXPECT_EQ(delays(plan, 7), (std::vector<long>{250, 500, 1000, 2000, 4000, 4000, 4000}));
  EXPECT_EQ(plan.retry_text(true), "; retrying when /dev/ttyUSB0 comes back, or in 4 s");
  EXPECT_EQ(plan.retry_text(false), "; retrying in 4 s");  // the watch could not be armed
}

TEST(ReconnectPlan, ATcpBridgeIsNotWatchedAndWaitsUnderASecond) {
  ReconnectPlan plan(backoff_config("tcp://192.168.1.20:2000"));
  EXPECT_FALSE(plan.watched_path());
  EXPECT_EQ(delays(plan, 4), (std::vector<long>{250, 500, 750, 750}));
  EXPECT_EQ(plan.retry_text(true), "; retrying in 0.75 s");
}

TEST(ReconnectPlan, AGoodStartBeginsTheWaitsAgain) {
  ReconnectPlan plan(backoff_config("/dev/ttyUSB0"));
  delays(plan, 5);
  plan.started();
  EXPECT_EQ(plan.delay(), 250ms);
}

TEST(ReconnectPlan, ALinkOpenedByItsOwnOpenerIsNeitherWatchedNorCapped) {
  SessionConfig config = backoff_config("/dev/ttyUSB0");
  config.open_link = [](boost::asio::io_context&, std::uint32_t, std::string&) -> std::unique_ptr<ByteLink> {
    return nullptr;
  };
  ReconnectPlan plan(config);
  EXPECT_FALSE(plan.watched_path());
  EXPECT_EQ(delays(plan, 6).back(), 4000);
}

// A regular file or a folder given as the port will never become one: the session says so once
// and stops, instead of "retrying when ... comes back" forever. A missing path may yet appear.
TEST(ReconnectPlan, APathThatIsNoDeviceIsHopelessAMissingOneIsNot) {
  const auto dir = std::filesystem::temp_directory_path() / ("ydscope-hopeless-" + std::to_string(::getpid()));
  std::filesystem::create_directories(dir);
  const auto file = dir / "lidar.txt";
  std::ofstream(file) << "not a port\n";
  EXPECT_TRUE(ReconnectPlan(backoff_config(file.string())).hopeless());
  EXPECT_TRUE(ReconnectPlan(backoff_config(dir.string())).hopeless());
  EXPECT_FALSE(ReconnectPlan(backoff_config((dir / "ttyUSB7").string())).hopeless()) << "it may be plugged in";
  EXPECT_FALSE(ReconnectPlan(backoff_config("/dev/null")).hopeless()) << "a character device";
  EXPECT_FALSE(ReconnectPlan(backoff_config("tcp://127.0.0.1:2000")).hopeless());
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace ydscope
