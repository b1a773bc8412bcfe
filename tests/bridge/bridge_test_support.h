#pragma once
// What the bridge tests share: the real server on 127.0.0.1, bounded waits on conditions, and the
// checks that a steady client got every lap and that the server still serves a newcomer.
#include <algorithm>
#include <chrono>
#include <memory>
#include <optional>
#include <string>
#include <thread>
#include <vector>

#include <gtest/gtest.h>

#include "bridge/scan_collector.h"
#include "support/ws_test_client.h"
#include "core/bridge/foxglove_server.h"
#include "core/bridge/ros_topic_channels.h"

namespace ydscope::test {

using foxglove::ClientStats;
using foxglove::FoxgloveServer;

// The real server on 127.0.0.1, a free port, the topics serve advertises.
inline std::unique_ptr<FoxgloveServer> start_server(foxglove::ServerOptions options = {}) {
  options.host = "127.0.0.1";
  options.port = 0;
  auto server = std::make_unique<FoxgloveServer>(options, foxglove::ros_topic_channels(), nullptr);
  std::string error;
  if (!server->start(error)) ADD_FAILURE() << error;
  return server;
}

inline std::optional<ClientStats> stats_of(const FoxgloveServer& server, std::uint16_t client_port) {
  const std::string peer = "127.0.0.1:" + std::to_string(client_port);
  for (const auto& c : server.clients())
    if (c.peer == peer) return c;
  return std::nullopt;
}

// Polls `condition` every 10 ms for at most `timeout`.
template <class Condition>
bool eventually(Condition condition, std::chrono::milliseconds timeout = 30s) {
  const auto deadline = std::chrono::steady_clock::now() + timeout;
  while (!condition()) {
    if (std::chrono::steady_clock::now() > deadline) return false;
    std::this_thread::sleep_for(10ms);
  }
  return true;
}

// Every lap the feed published from the collector's first one to its last, nothing else; and
// it got at least as far as `last`.
inline void expect_every_lap(const ScanCollector& collector, const std::vector<std::uint64_t>& published,
                             std::uint64_t last) {
  EXPECT_FALSE(collector.failed()) << "the steady client timed out or was disconnected";
  const auto got = collector.times();
  ASSERT_FALSE(got.empty());
  EXPECT_GE(got.back(), last);
  const auto first = std::find(published.begin(), published.end(), got.front());
  const auto end = std::find(published.begin(), published.end(), got.back());
  ASSERT_NE(first, published.end()) << "the steady client got a lap the feed never published";
  ASSERT_NE(end, published.end()) << "the steady client got a lap the feed never published";
  const std::vector<std::uint64_t> expected(first, end + 1);
  EXPECT_EQ(got, expected) << "laps lost, repeated or out of order: got " << got.size() << ", published "
                           << expected.size();
  EXPECT_GE(got.size(), 20u) << "too few laps to prove anything";
}

// A new client still gets served: handshake, advertise, a /scan lap.
inline void expect_still_serving(std::uint16_t port) {
  WsTestClient probe(port);
  ASSERT_TRUE(probe.subscribe(7, "/scan"));
  const auto message = probe.read_binary();
  ASSERT_TRUE(message) << "a new client got no /scan";
  EXPECT_EQ(message->subscription, 7u);
  probe.close_handshake();
}

}  // namespace ydscope::test
