// The bridge under abuse, with real WebSocket clients (Boost.Beast, tests/bridge/ws_test_client.h)
// against the real server on 127.0.0.1, fed by the virtual G6 through the same encoder serve uses:
// clients churning, a client that never reads, clients vanishing mid-frame. Each time the steady
// clients must get every lap, in order, and the server must go on serving. Loops are bounded in
// count, every wait in time; nothing asserts on how long anything took.
#include <atomic>
#include <string>
#include <thread>
#include <vector>

#include <gtest/gtest.h>

#include "bridge/bridge_test_support.h"
#include "bridge/lidar_feed.h"

namespace ydscope::test {
namespace {

TEST(BridgeStress, FiftyClientsChurningLeaveTheSteadyClientEveryLap) {
  auto server = start_server();
  LidarFeed feed(*server, 2.0);
  ScanCollector steady(server->port());
  ASSERT_TRUE(steady.subscribed());

  constexpr int kRounds = 4;
  constexpr int kClients = 50;
  std::atomic<int> served{0};
  std::atomic<int> failures{0};
  for (int round = 0; round < kRounds; ++round) {
    std::vector<std::thread> clients;
    for (int i = 0; i < kClients; ++i) {
      clients.emplace_back([&, i] {
        try {
          WsTestClient client(server->port());
          // Some also take /points, so the server is mid-write to them when they go.
          if (!client.subscribe(1, "/scan") || (i % 2 && !client.subscribe(2, "/points"))) {
            ++failures;
            return;
          }
          if (i % 5 == 4) return client.close_socket();  // gone before its first lap
          if (!client.read_binary()) {
            ++failures;
            return;
          }
          ++served;
          switch (i % 5) {
            case 0: return client.close_handshake();
            case 1: return client.close_socket();
            case 2: return client.reset_socket();
            default: return;  // destroyed with messages still unread
          }
        } catch (const std::exception&) {
          ++failures;
        }
      });
    }
    for (auto& t : clients) t.join();
  }
  EXPECT_EQ(failures.load(), 0);
  EXPECT_EQ(served.load(), kRounds * kClients * 4 / 5);
  // Every churned client is gone from the server; only the steady one is left.
  EXPECT_TRUE(eventually([&] { return server->clients().size() == 1; })) << server->clients().size() << " clients left";

  ASSERT_TRUE(feed.wait_for_scans(feed.scan_times().size() + 25, 60s));
  const std::uint64_t last = feed.scan_times().back();
  steady.finish_at(last);
  expect_every_lap(steady, feed.scan_times(), last);
  const auto stats = stats_of(*server, steady.local_port());
  ASSERT_TRUE(stats);
  EXPECT_EQ(stats->dropped, 0u);
  expect_still_serving(server->port());
}

TEST(BridgeStress, AClientThatNeverReadsLosesOnlyItsOwnLapsAndTheyAreCounted) {
  auto server = start_server();
  LidarFeed feed(*server, 4.0);
  ScanCollector steady_a(server->port());
  ScanCollector steady_b(server->port());
  // A small receive window, so the server's writes to it stall soon.
  WsTestClient slow(server->port(), 4096);
  ASSERT_TRUE(steady_a.subscribed() && steady_b.subscribed());
  ASSERT_TRUE(slow.subscribe(1, "/scan") && slow.subscribe(2, "/points"));

  // It reads nothing until its queue has overflowed well past its 64 messages.
  ASSERT_TRUE(eventually(
      [&] {
        const auto s = stats_of(*server, slow.local_port());
        return s && s->dropped > 200;
      },
      120s))
      << "the never-reading client's drops were not counted";

  const std::uint64_t last = feed.scan_times().back();
  steady_a.finish_at(last);
  steady_b.finish_at(last);
  const auto published = feed.scan_times();
  expect_every_lap(steady_a, published, last);
  expect_every_lap(steady_b, published, last);
  for (const ScanCollector* steady : {&steady_a, &steady_b}) {
    const auto stats = stats_of(*server, steady->local_port());
    ASSERT_TRUE(stats);
    EXPECT_EQ(stats->dropped, 0u);
  }

  // Now it reads: what it got is in order, the newest laps reach it (the oldest went), it was
  // told, and every /scan it missed is in its drop counter.
  std::vector<std::uint64_t> scans;
  bool warned = false;
  while (scans.empty() || scans.back() < last) {
    const auto message = slow.read(30s);
    ASSERT_TRUE(message) << "the slow client stopped getting messages";
    if (message->text)
      warned = warned || message->json.find("messages dropped") != std::string::npos;
    else if (message->subscription == 1)
      scans.push_back(message->log_time_ns);
  }
  ASSERT_FALSE(scans.empty());
  EXPECT_TRUE(std::is_sorted(scans.begin(), scans.end()));
  EXPECT_EQ(std::adjacent_find(scans.begin(), scans.end()), scans.end()) << "a lap came twice";
  const auto all = feed.scan_times();
  const auto from = std::find(all.begin(), all.end(), scans.front());
  const auto to = std::find(all.begin(), all.end(), scans.back());
  ASSERT_NE(from, all.end());
  ASSERT_NE(to, all.end());
  const auto missed = static_cast<std::uint64_t>(to - from + 1) - scans.size();
  EXPECT_GT(missed, 0u);
  EXPECT_TRUE(warned) << "the slow client got no status message about its drops";
  const auto stats = stats_of(*server, slow.local_port());
  ASSERT_TRUE(stats);
  EXPECT_GE(stats->dropped, missed);
  expect_still_serving(server->port());
}

// A masked client text frame header announcing `length` bytes (RFC 6455 5.2), for half frames.
std::string client_frame_header(std::uint16_t length) {
  std::string header = {'\x81', '\xFE', static_cast<char>(length >> 8), static_cast<char>(length & 0xFF)};
  return header + std::string("\x12\x34\x56\x78", 4);
}

TEST(BridgeStress, ClientsVanishingMidFrameLeaveTheServerAndOthersUntouched) {
  auto server = start_server();
  LidarFeed feed(*server, 2.0);
  ScanCollector steady(server->port());
  ASSERT_TRUE(steady.subscribed());

  constexpr int kVanishing = 40;
  for (int i = 0; i < kVanishing; ++i) {
    WsTestClient client(server->port(), i % 4 == 3 ? 4096 : 0);
    ASSERT_FALSE(client.closed());
    switch (i % 4) {
      case 0:  // half of a frame's payload, then FIN
        ASSERT_TRUE(client.write_raw(client_frame_header(400) + std::string(200, 'x')));
        client.close_socket();
        break;
      case 1:  // half of a frame's payload, then RST
        ASSERT_TRUE(client.write_raw(client_frame_header(400) + std::string(200, 'x')));
        client.reset_socket();
        break;
      case 2:  // half of a frame's header, then RST
        ASSERT_TRUE(client.write_raw(client_frame_header(400).substr(0, 3)));
        client.reset_socket();
        break;
      default:  // gone half way through a frame the server is sending (a /points lap)
        ASSERT_TRUE(client.subscribe(2, "/points"));
        ASSERT_GT(client.read_raw(100), 0u);
        client.reset_socket();
        break;
    }
  }
  EXPECT_TRUE(eventually([&] { return server->clients().size() == 1; })) << server->clients().size() << " clients left";

  ASSERT_TRUE(feed.wait_for_scans(feed.scan_times().size() + 25, 60s));
  const std::uint64_t last = feed.scan_times().back();
  steady.finish_at(last);
  expect_every_lap(steady, feed.scan_times(), last);
  const auto stats = stats_of(*server, steady.local_port());
  ASSERT_TRUE(stats);
  EXPECT_EQ(stats->dropped, 0u);
  expect_still_serving(server->port());
}

}  // namespace
}  // namespace ydscope::test
