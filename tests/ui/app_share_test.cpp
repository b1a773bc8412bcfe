// The app's Share, as a Foxglove user meets it: with --share a WebSocket client connects to the
// app and receives /scan of the app's source (the virtual G6: its range limits, its points); W
// stops serving (the client is let go, nobody can connect) and W again serves anew; quitting
// stops cleanly. A port already in use is one sentence, and the app goes on showing the lidar.
#include <gtest/gtest.h>

#include <fstream>
#include <memory>
#include <sstream>

#include "app_test_support.h"
#include "support/ws_test_client.h"
#include "export/laser_scan_reader.h"
#include "private_display.h"
#include "share_client.h"
#include "x11_input.h"

namespace ydscope::test {
namespace {

#ifdef YDSCOPE_APP_PATH

// Reads until the server lets the client go; false if it still talks after `timeout`.
bool let_go(WsTestClient& client, std::chrono::seconds timeout) {
  const auto deadline = std::chrono::steady_clock::now() + timeout;
  while (std::chrono::steady_clock::now() < deadline)
    if (!client.read(std::chrono::seconds(1)) && client.closed()) return true;
  return false;
}

TEST(AppShare, AFoxgloveClientGetsTheScanAndWTogglesTheShare) {
  if (std::system("command -v Xvfb >/dev/null 2>&1") != 0) GTEST_SKIP() << "Xvfb is not installed";
  const PrivateDisplay display;
  ASSERT_TRUE(display) << "could not start an Xvfb of the test's own";
  X11Hands hands;
  ASSERT_TRUE(hands) << "cannot open the X display";
  const std::uint16_t port = free_port();
  ASSERT_NE(port, 0);
  const std::filesystem::path dir = fresh_temp_dir("ydscope-app-share");
  const pid_t app = spawn_in(dir, {YDSCOPE_APP_PATH, "--sim", "G6", "--share", "--share-port", std::to_string(port)});
  ASSERT_TRUE(hands.find_window("ydscope", std::chrono::seconds(30)));

  auto client = connect_to(port, std::chrono::seconds(30));
  ASSERT_TRUE(client) << "nothing served on 127.0.0.1:" << port;
  ASSERT_TRUE(client->subscribe(1, "/scan"));
  for (int i = 0; i < 5; ++i) {
    const auto message = client->read_binary(std::chrono::seconds(15));
    ASSERT_TRUE(message) << "no /scan message " << i;
    EXPECT_EQ(message->subscription, 1u);
    const ScanSeen scan = laser_scan(message->payload);
    EXPECT_EQ(scan.frame_id, "laser");
    EXPECT_FLOAT_EQ(scan.range_max, 25.0f) << "the G6's range, so the app's source";
    EXPECT_GT(scan.bins, 500u);
    EXPECT_GT(scan.returns, 500u) << "the virtual G6's demo scene, not an empty scan";
  }

  hands.tap(XK_w, 1);  // share off
  EXPECT_TRUE(let_go(*client, std::chrono::seconds(15))) << "the server kept the client after W";
  EXPECT_THROW(WsTestClient(port, 0, std::chrono::seconds(2)), std::runtime_error) << "still serving after W";

  hands.tap(XK_w, 1);  // and on again
  auto again = connect_to(port, std::chrono::seconds(20));
  ASSERT_TRUE(again) << "W did not serve again";
  ASSERT_TRUE(again->subscribe(7, "/scan"));
  const auto message = again->read_binary(std::chrono::seconds(15));
  ASSERT_TRUE(message);
  EXPECT_EQ(message->subscription, 7u);

  EXPECT_EQ(stop_process(app, SIGTERM), 0) << "quitting while shared";
  EXPECT_TRUE(let_go(*again, std::chrono::seconds(10))) << "the client outlived the app";
  if (!HasFailure()) std::filesystem::remove_all(dir);
}

TEST(AppShare, APortInUseIsOneSentenceAndTheAppGoesOn) {
  if (std::system("command -v Xvfb >/dev/null 2>&1") != 0) GTEST_SKIP() << "Xvfb is not installed";
  const PrivateDisplay display;
  ASSERT_TRUE(display) << "could not start an Xvfb of the test's own";
  X11Hands hands;
  ASSERT_TRUE(hands) << "cannot open the X display";
  const Listener taken;
  ASSERT_NE(taken.port, 0);
  const std::filesystem::path dir = fresh_temp_dir("ydscope-app-share-busy");
  const std::string command = std::string("exec '") + YDSCOPE_APP_PATH + "' --sim G6 --share --share-port " +
                              std::to_string(taken.port) + " 2>stderr.txt";
  const pid_t app = spawn_in(dir, {"/bin/sh", "-c", command});
  ASSERT_TRUE(hands.find_window("ydscope", std::chrono::seconds(30)));
  const std::string expected = "ydscope: Share did not start: cannot listen on 127.0.0.1:" + std::to_string(taken.port);
  std::string said;
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(20);
  while (std::chrono::steady_clock::now() < deadline && said.find(expected) == std::string::npos) {
    std::this_thread::sleep_for(std::chrono::milliseconds(200));
    std::ifstream in(dir / "stderr.txt");
    std::stringstream text;
    text << in.rdbuf();
    said = text.str();
  }
  const std::string line = said.substr(said.find("ydscope: Share"),
                                       said.find('\n', said.find("ydscope: Share")) - said.find("ydscope: Share"));
  EXPECT_NE(said.find(expected), std::string::npos) << said;
  EXPECT_NE(line.find("in use"), std::string::npos) << line;
  EXPECT_EQ(line.back(), '.') << "one sentence: " << line;
  std::this_thread::sleep_for(std::chrono::seconds(2));
  EXPECT_EQ(::kill(app, 0), 0) << "the app went away";
  EXPECT_EQ(stop_process(app, SIGTERM), 0);
  if (!HasFailure()) std::filesystem::remove_all(dir);
}

#endif

}  // namespace
}  // namespace ydscope::test
