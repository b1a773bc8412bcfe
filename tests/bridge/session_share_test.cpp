// SessionShare follows the source: a client stays connected while the session moves from a
// virtual G6 to a virtual G1, and once the share attaches to the new source its /scan is the
// G1's (its range limits), decoded with a fresh decoder rather than the G6's.
#include <gtest/gtest.h>

#include "support/ws_test_client.h"
#include "core/bridge/session_share.h"
#include "export/laser_scan_reader.h"
#include "support/session_test_support.h"

namespace ydscope {
namespace {

using namespace test;

// Reads /scan messages until one has `range_max`; false after `timeout`.
bool scan_with_range_max(WsTestClient& client, float range_max, std::chrono::seconds timeout) {
  const auto deadline = std::chrono::steady_clock::now() + timeout;
  while (std::chrono::steady_clock::now() < deadline) {
    const auto message = client.read_binary(std::chrono::seconds(2));
    if (message && laser_scan(message->payload).range_max == range_max) return true;
    if (client.closed()) return false;
  }
  return false;
}

TEST(SessionShare, FollowsANewSourceWithItsClientsStillConnected) {
  SimOnPty g6(Model::G6), g1(Model::G1);
  Session session(4);
  ShareOptions options;
  options.server.port = 0;
  std::string error;
  auto share = SessionShare::start({{&session, {}}}, options, error);
  ASSERT_TRUE(share) << error;
  EXPECT_EQ(share->address(), "ws://127.0.0.1:" + std::to_string(share->port()));
  session.connect(config_for(g6.port()));

  WsTestClient client(share->port());
  ASSERT_TRUE(client.subscribe(1, "/scan"));
  ASSERT_TRUE(scan_with_range_max(client, range_limits(Model::G6).max_m, std::chrono::seconds(20)));

  share->topics().detach();
  session.connect(config_for(g1.port()));
  const auto g1_scanning = [](const SessionSnapshot& s) {
    return s.state == LinkState::Scanning && s.device && s.device->profile && s.device->profile->model == Model::G1;
  };
  ASSERT_TRUE(g1_scanning(session.wait_until(g1_scanning, kPatience)));
  share->topics().attach();
  EXPECT_TRUE(scan_with_range_max(client, range_limits(Model::G1).max_m, std::chrono::seconds(20)))
      << "the share did not serve the new source";
  EXPECT_FALSE(client.closed());
  EXPECT_EQ(share->clients().size(), 1u);
  EXPECT_TRUE(share->stop());
}

// Foxglove lists every status message under Problems, info too: a lidar that connects, probes
// and scans as it should gives the clients laps and no status at all.
TEST(SessionShare, RoutineLinkStatesAreNoStatusMessages) {
  SimOnPty g6(Model::G6);
  Session session(4);
  ShareOptions options;
  options.server.port = 0;
  std::string error;
  auto share = SessionShare::start({{&session, {}}}, options, error);
  ASSERT_TRUE(share) << error;
  WsTestClient client(share->port());
  ASSERT_TRUE(client.subscribe(1, "/scan"));
  session.connect(config_for(g6.port()));

  std::vector<std::string> statuses;
  std::size_t scans = 0;
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(20);
  while (scans < 5 && std::chrono::steady_clock::now() < deadline && !client.closed()) {
    const auto message = client.read(std::chrono::seconds(2));
    if (!message) continue;
    if (!message->text)
      ++scans;
    else if (message->json.find(R"("op":"status")") != std::string::npos)
      statuses.push_back(message->json);
  }
  EXPECT_GE(scans, 5u);
  EXPECT_TRUE(statuses.empty()) << statuses.size() << " status messages, the first: " << statuses.front();
  EXPECT_TRUE(share->stop());
}

TEST(SessionShare, APortInUseIsOneSentenceNamingTheOption) {
  Session session(4);
  ShareOptions first_options;
  first_options.server.port = 0;
  std::string error;
  auto first = SessionShare::start({{&session, {}}}, first_options, error);
  ASSERT_TRUE(first) << error;
  ShareOptions second_options;
  second_options.server.port = first->port();
  second_options.server.port_option = "--share-port";
  EXPECT_FALSE(SessionShare::start({{&session, {}}}, second_options, error));
  EXPECT_NE(error.find("cannot listen on 127.0.0.1:" + std::to_string(first->port())), std::string::npos) << error;
  EXPECT_NE(error.find("choose another port with --share-port"), std::string::npos) << error;
}

}  // namespace
}  // namespace ydscope
