// Misbehaving clients beside a steady one (issue 26, "under load and abuse"): a client that never
// reads, clients reset mid-stream, oversized messages, malformed messages and bytes that are no
// WebSocket at all. For each, the real server on 127.0.0.1, fed by the virtual G6, must keep the
// steady client at full rate while the abuse goes on (the laps it received over that interval
// against the laps published over the same interval), then have given it every lap, in order; hold
// no more for a client that does not read than its send queue's cap; answer every malformed
// message with a status of level error and go on serving that client; and accept newcomers after.
// Loops are bounded in count, every wait in time; nothing asserts on how long anything took.
#include <algorithm>
#include <array>
#include <atomic>
#include <functional>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include <boost/asio/write.hpp>
#include <boost/property_tree/json_parser.hpp>
#include <boost/property_tree/ptree.hpp>
#include <gtest/gtest.h>

#include "bridge/bridge_test_support.h"
#include "bridge/lidar_feed.h"

namespace ydscope::test {
namespace {

// The pace is judged over at least this many laps published while the abuse goes on, at every
// lap: the steady client may be behind by kSlack laps more than when the abuse began (a lap in
// flight, a stall of the shared machine: 0.5 s at the feed's 16 laps/s). A server stalled by the
// abuse, or a slow client's laps queued ahead of it, falls further behind.
constexpr std::size_t kPaceLaps = 60;
constexpr std::size_t kSlack = 8;

// Runs `abuse(round)` over and over, until it returns true (it has done all it came to do) and the
// feed has published kPaceLaps since it began; meanwhile, each time the feed publishes a lap, the
// laps the steady client received since the start are compared with the laps published since.
template <class Abuse>
void expect_full_rate_while(LidarFeed& feed, const ScanCollector& steady, Abuse abuse) {
  ASSERT_TRUE(eventually([&] { return steady.count() >= 3; }, 60s)) << "the steady client got no laps";
  const std::size_t published0 = feed.scan_times().size();
  const std::size_t received0 = steady.count();
  std::atomic<bool> abusing{true};
  std::atomic<std::size_t> worst_behind{0};
  std::thread pace([&] {
    for (std::size_t published = published0; abusing.load();) {
      if (!feed.wait_for_scans(published + 1, 1s)) continue;
      published = feed.scan_times().size();
      const std::size_t received = steady.count() - received0;
      const std::size_t behind = published - published0 > received ? published - published0 - received : 0;
      if (behind > worst_behind.load()) worst_behind.store(behind);
    }
  });
  const auto deadline = std::chrono::steady_clock::now() + 180s;
  bool done = false;
  for (int round = 0; !done || feed.scan_times().size() < published0 + kPaceLaps; ++round) {
    done = abuse(round) || done;
    if (::testing::Test::HasFatalFailure() || std::chrono::steady_clock::now() > deadline) break;
  }
  const std::size_t published = feed.scan_times().size() - published0;
  const std::size_t received = steady.count() - received0;
  abusing.store(false);
  pace.join();
  if (::testing::Test::HasFatalFailure()) return;
  ASSERT_TRUE(done && published >= kPaceLaps) << "the abuse did not finish in 180 s";
  EXPECT_LE(worst_behind.load(), kSlack) << "the steady client fell " << worst_behind.load()
                                         << " laps behind while others misbehaved";
  EXPECT_GE(received + kSlack, published) << "the steady client fell behind while others misbehaved: received "
                                          << received << " laps while " << published << " were published";
}

// After the abuse: the steady client got every lap up to the newest, and dropped none.
void expect_every_lap_after(FoxgloveServer& server, LidarFeed& feed, ScanCollector& steady) {
  ASSERT_TRUE(feed.wait_for_scans(feed.scan_times().size() + 5, 60s));
  const std::uint64_t last = feed.scan_times().back();
  steady.finish_at(last);
  expect_every_lap(steady, feed.scan_times(), last);
  const auto stats = stats_of(server, steady.local_port());
  ASSERT_TRUE(stats) << "the steady client is gone from the server";
  EXPECT_EQ(stats->dropped, 0u);
}

struct Status {
  int level = -1;
  std::string message;
};

// The next status message, skipping every other message, parsed as a client would; empty when
// none came within `timeout` or the connection ended.
std::optional<Status> next_status(WsTestClient& client, std::chrono::milliseconds timeout = 10s) {
  const auto deadline = std::chrono::steady_clock::now() + timeout;
  for (;;) {
    const auto left =
        std::chrono::duration_cast<std::chrono::milliseconds>(deadline - std::chrono::steady_clock::now());
    if (left <= 0ms) return std::nullopt;
    const auto message = client.read(left);
    if (!message) return std::nullopt;
    if (!message->text) continue;
    boost::property_tree::ptree tree;
    std::istringstream in(message->json);
    boost::property_tree::read_json(in, tree);
    if (tree.get<std::string>("op", "") != "status") continue;
    return Status{tree.get<int>("level", -1), tree.get<std::string>("message", "")};
  }
}

// Every byte of a literal, NULs included.
template <std::size_t N>
std::string bytes(const char (&literal)[N]) {
  return std::string(literal, N - 1);
}

// A masked client frame (RFC 6455 5.2) with the FIN bit, opcode `opcode` and a mask key of zero
// (a legal key that leaves the payload as it is), for frames a WebSocket library would not send.
// Payloads under 64 KiB.
std::string masked_frame(std::uint8_t opcode, std::string_view payload) {
  std::string frame{static_cast<char>(0x80 | opcode)};
  if (payload.size() < 126) {
    frame += static_cast<char>(0x80 | payload.size());
  } else {
    frame += static_cast<char>(0x80 | 126);
    frame += static_cast<char>(payload.size() >> 8);
    frame += static_cast<char>(payload.size() & 0xFF);
  }
  frame += std::string(4, '\0');
  return frame + std::string(payload);
}

// Connects, writes `bytes` where the HTTP upgrade belongs, and reads until the server ends the
// connection (true) or 30 s pass (false).
bool closed_after_bytes_before_handshake(std::uint16_t port, std::string_view bytes) {
  namespace asio = boost::asio;
  asio::io_context io;
  asio::ip::tcp::socket socket(io);
  boost::system::error_code ec;
  socket.connect({asio::ip::make_address("127.0.0.1"), port}, ec);
  if (ec) return false;
  asio::write(socket, asio::buffer(bytes.data(), bytes.size()), ec);
  if (ec) return true;  // already reset
  bool ended = false;
  std::array<char, 4096> buffer{};
  std::function<void()> read_on = [&] {
    socket.async_read_some(asio::buffer(buffer), [&](const boost::system::error_code& read_ec, std::size_t) {
      if (read_ec)
        ended = true;
      else
        read_on();
    });
  };
  read_on();
  io.run_for(30s);
  socket.close(ec);  // before the handler's references go
  return ended;
}

TEST(BridgeAbuse, ClientsThatNeverReadHoldNoMoreThanTheirQueueAndTheOthersKeepFullRate) {
  foxglove::ServerOptions options;
  options.client_queue = 16;
  auto server = start_server(options);
  LidarFeed feed(*server, 2.0);
  ScanCollector steady(server->port());
  ASSERT_TRUE(steady.subscribed());
  // Small receive windows, so the server's writes to them stall soon. One is silent; the other
  // keeps sending requests, each answered with a status that queues up behind the laps.
  WsTestClient silent(server->port(), 4096);
  WsTestClient asking(server->port(), 4096);
  for (WsTestClient* slow : {&silent, &asking})
    ASSERT_TRUE(slow->subscribe(1, "/scan") && slow->subscribe(2, "/points"));

  const std::string bad_op = R"({"op":")" + std::string(60'000, 'z') + R"("})";
  std::size_t most_queued = 0;
  std::size_t most_queued_bytes = 0;
  expect_full_rate_while(feed, steady, [&](int) {
    // Once a lap: what the slow ones hold, and a burst of bad requests from the asking one.
    feed.wait_for_scans(feed.scan_times().size() + 1, 5s);
    for (int i = 0; i < 20; ++i)
      EXPECT_TRUE(asking.send_text(i ? R"({"op":"unsubscribe","subscriptionIds":[99]})" : bad_op));
    bool both_dropped = true;
    for (const WsTestClient* slow : {&silent, &asking}) {
      const auto stats = stats_of(*server, slow->local_port());
      if (!stats) {
        ADD_FAILURE() << "a client that does not read was closed";
        return true;
      }
      most_queued = std::max(most_queued, stats->queued);
      most_queued_bytes = std::max(most_queued_bytes, stats->queued_bytes);
      both_dropped = both_dropped && stats->dropped > 50;
    }
    return both_dropped;  // both queues have overflowed well past their cap
  });
  EXPECT_LE(most_queued, options.client_queue);
  // Laps and the status texts, which are shorter than any lap.
  const std::size_t largest = feed.largest_message() + 13;
  EXPECT_LE(most_queued_bytes, options.client_queue * largest)
      << "a slow client held " << most_queued_bytes << " bytes; " << options.client_queue << " of the largest message ("
      << largest << " bytes) is the cap";
  EXPECT_GT(most_queued_bytes, 0u);
  expect_every_lap_after(*server, feed, steady);
  expect_still_serving(server->port());
}

TEST(BridgeAbuse, ClientsResetMidStreamLeaveTheOthersAtFullRate) {
  auto server = start_server();
  LidarFeed feed(*server, 2.0);
  ScanCollector steady(server->port());
  ASSERT_TRUE(steady.subscribed());

  int reset = 0;
  expect_full_rate_while(feed, steady, [&](int round) {
    WsTestClient client(server->port(), round % 2 ? 4096 : 0);
    EXPECT_TRUE(client.subscribe(1, "/scan") && client.subscribe(2, "/points"));
    // Gone part way through a frame the server is sending, or before the first one.
    if (round % 3 != 2) {
      EXPECT_GT(client.read_raw(1000), 0u);
    }
    client.reset_socket();
    return ++reset >= 30;
  });
  EXPECT_TRUE(eventually([&] { return server->clients().size() == 1; })) << server->clients().size() << " clients left";
  expect_every_lap_after(*server, feed, steady);
  expect_still_serving(server->port());
}

TEST(BridgeAbuse, OversizedMessagesAreRefusedWithAnErrorStatusAndTheOthersKeepFullRate) {
  auto server = start_server();
  LidarFeed feed(*server, 2.0);
  ScanCollector steady(server->port());
  ASSERT_TRUE(steady.subscribed());

  const std::string big_text = R"({"op":"subscribe","subscriptions":[)" + std::string(200'000, ' ') + "]}";
  const std::string big_binary(1 << 20, '\x02');
  const std::string beyond_any_limit(20u << 20, 'x');
  expect_full_rate_while(feed, steady, [&](int round) {
    WsTestClient client(server->port());
    // Above the server's limit for a request, below the size where it gives up on the
    // connection: refused with an error status, and the client is still served.
    EXPECT_TRUE(client.send_text(big_text));
    auto status = next_status(client);
    EXPECT_TRUE(status && status->level == 2 && status->message.find("limit") != std::string::npos)
        << (status ? status->message : "no status");
    EXPECT_TRUE(client.send_binary(big_binary));
    status = next_status(client);
    EXPECT_TRUE(status && status->level == 2) << (status ? status->message : "no status");
    EXPECT_TRUE(client.subscribe(3, "/scan"));
    const auto lap = client.read_binary();
    EXPECT_TRUE(lap && lap->subscription == 3) << "the client was not served after its oversized messages";
    // Beyond any size the server reads: that connection ends, and only it. The server may close
    // it before the message is all written, so the write may fail.
    WsTestClient huge(server->port());
    if (round % 2)
      huge.send_text(beyond_any_limit, 30s);
    else  // a frame that announces 2^40 bytes
      huge.write_raw("\x82\xFF" + bytes("\x00\x00\x01\x00\x00\x00\x00\x00") + std::string(4, '\0') + "abc");
    // What the server sent before (serverInfo, advertise) still comes; then the connection ends.
    bool ended = false;
    for (int i = 0; i < 100 && !ended; ++i) ended = !huge.read(30s);
    EXPECT_TRUE(ended) << "a message beyond any limit left its connection open";
    return round >= 5;
  });
  EXPECT_TRUE(eventually([&] { return server->clients().size() == 1; })) << server->clients().size() << " clients left";
  expect_every_lap_after(*server, feed, steady);
  expect_still_serving(server->port());
}

struct Malformed {
  const char* what;
  std::string message;
  bool binary = false;
  const char* says;  // in the status message
};

std::vector<Malformed> malformed_messages() {
  return {
      {"not JSON", "this is not JSON {", false, "not JSON"},
      {"empty", "", false, "not JSON"},
      {"no op", R"({"subscriptions":[]})", false, "\"op\""},
      {"unknown op", R"({"op":"advertise","channels":[]})", false, "not supported"},
      {"an op of 60 KiB", R"({"op":")" + std::string(60'000, 'z') + R"("})", false, "not supported"},
      {"op not a string", R"({"op":{"nested":1}})", false, "op"},
      {"subscriptions not an array", R"({"op":"subscribe","subscriptions":"all"})", false, "array"},
      {"subscription id not a number", R"({"op":"subscribe","subscriptions":[{"id":"x","channelId":1}]})", false,
       "numeric"},
      {"subscribe to a channel never advertised", R"({"op":"subscribe","subscriptions":[{"id":5,"channelId":4242}]})",
       false, "4242"},
      {"unsubscribe of an unknown subscription", R"({"op":"unsubscribe","subscriptionIds":[4242]})", false, "4242"},
      {"nested 10 000 deep", std::string(10'000, '['), false, "nested"},
      {"binary garbage", bytes("\x01\xFF\x00\x13garbage\x00\x00"), true, "binary"},
  };
}

TEST(BridgeAbuse, MalformedMessagesGetAnErrorStatusAndTheConnectionGoesOn) {
  auto server = start_server();
  LidarFeed feed(*server, 2.0);
  ScanCollector steady(server->port());
  ASSERT_TRUE(steady.subscribed());

  const auto cases = malformed_messages();
  expect_full_rate_while(feed, steady, [&](int round) {
    WsTestClient client(server->port());
    // Subscribed first: a malformed message must not cost the client its subscription.
    EXPECT_TRUE(client.subscribe(1, "/scan"));
    for (const Malformed& m : cases) {
      EXPECT_TRUE(m.binary ? client.send_binary(m.message) : client.send_text(m.message)) << m.what;
      const auto status = next_status(client);
      if (!status) {
        ADD_FAILURE() << m.what << ": no status message came back";
        return true;
      }
      EXPECT_EQ(status->level, 2) << m.what << ": " << status->message;
      EXPECT_NE(status->message.find(m.says), std::string::npos) << m.what << ": " << status->message;
      // It names the trouble; it does not echo a client's kilobytes back.
      EXPECT_LT(status->message.size(), 300u) << m.what << ": a status of " << status->message.size() << " bytes";
    }
    const auto lap = client.read_binary();
    EXPECT_TRUE(lap && lap->subscription == 1) << "the client lost its subscription to its malformed messages";
    client.close_handshake();
    return round >= 3;
  });
  expect_every_lap_after(*server, feed, steady);
  expect_still_serving(server->port());
}

// Bytes that break the WebSocket protocol itself leave nothing to answer on that connection: the
// server ends it (as RFC 6455 says to) and only it.
TEST(BridgeAbuse, BytesThatAreNoWebSocketEndOnlyTheirConnection) {
  auto server = start_server();
  LidarFeed feed(*server, 2.0);
  ScanCollector steady(server->port());
  ASSERT_TRUE(steady.subscribed());

  const std::vector<std::pair<const char*, std::string>> cases = {
      {"random bytes", bytes("\x13\x37\xC0\xFF\xEE\x00\x42 not a frame at all \xFF\xFE")},
      {"an unmasked client frame", bytes("\x81\x05hello")},
      {"a reserved opcode", masked_frame(0x3, "abc")},
      {"a text frame that is not UTF-8", masked_frame(0x1, "{\"op\":\"\xC3\x28\"}")},
      {"a control frame of 200 bytes", masked_frame(0x9, std::string(200, 'p'))},
  };
  expect_full_rate_while(feed, steady, [&](int round) {
    for (const auto& [what, bytes] : cases) {
      WsTestClient client(server->port());
      EXPECT_TRUE(client.subscribe(1, "/scan")) << what;
      EXPECT_TRUE(client.write_raw(bytes)) << what;
      // Whatever was on its way still comes; then the connection ends.
      bool ended = false;
      for (int i = 0; i < 1000 && !ended; ++i) ended = !client.read(30s);
      EXPECT_TRUE(ended) << what << ": the connection stayed open";
    }
    // Not even HTTP.
    EXPECT_TRUE(closed_after_bytes_before_handshake(server->port(), bytes("\x16\x03\x01\x02\x00 hello\r\n\r\n")));
    EXPECT_TRUE(closed_after_bytes_before_handshake(server->port(), std::string(100'000, 'G')));
    return round >= 3;
  });
  EXPECT_TRUE(eventually([&] { return server->clients().size() == 1; })) << server->clients().size() << " clients left";
  expect_every_lap_after(*server, feed, steady);
  expect_still_serving(server->port());
}

}  // namespace
}  // namespace ydscope::test
