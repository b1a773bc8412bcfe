// Peers that go quiet: a connection that never finishes the WebSocket handshake, and a client
// that stops answering the server's keep-alive pings (gone without FIN or RST), are closed, so
// they cannot hold sockets for ever; a client that keeps reading is never closed by the pings.
// Short timeouts here; every wait is a bounded wait on a condition.
#include <string>

#include <boost/asio/connect.hpp>
#include <boost/asio/io_context.hpp>
#include <boost/asio/ip/tcp.hpp>
#include <boost/asio/read.hpp>
#include <boost/asio/write.hpp>
#include <gtest/gtest.h>

#include "bridge/bridge_test_support.h"
#include "bridge/lidar_feed.h"

namespace ydscope::test {
namespace {

namespace asio = boost::asio;
using tcp = asio::ip::tcp;

// Regression: the HTTP upgrade had no timeout, so a silent connection stayed a client for ever.
TEST(BridgeTimeouts, ConnectionsThatNeverFinishTheHandshakeAreClosed) {
  foxglove::ServerOptions options;
  options.handshake_timeout = 300ms;
  auto server = start_server(options);
  asio::io_context io;
  std::vector<tcp::socket> silent;
  for (int i = 0; i < 6; ++i) {
    silent.emplace_back(io);
    silent.back().connect({asio::ip::make_address("127.0.0.1"), server->port()});
    if (i % 2)
      asio::write(silent.back(), asio::buffer(std::string("GET / HTTP/1.1\r\nHost: 127.0.0.1\r\n")));  // half a request
  }
  ASSERT_TRUE(eventually([&] { return server->clients().size() == 6; })) << "the server did not accept them";
  EXPECT_TRUE(eventually([&] { return server->clients().empty(); }))
      << server->clients().size() << " silent connections kept";
  // The server closed them: each reads end-of-file (the server sends nothing before the upgrade).
  for (auto& socket : silent) {
    char byte = 0;
    boost::system::error_code ec;
    asio::read(socket, asio::buffer(&byte, 1), ec);
    EXPECT_EQ(ec, asio::error::eof);
  }
  WsTestClient newcomer(server->port());  // still accepting: handshake and advertise
  EXPECT_NE(newcomer.channel_of("/scan"), 0u);
}

TEST(BridgeTimeouts, AClientThatStopsAnsweringPingsIsClosedAndAReadingOneIsNot) {
  foxglove::ServerOptions options;
  options.idle_timeout = 600ms;
  auto server = start_server(options);
  LidarFeed feed(*server, 2.0);
  ScanCollector steady(server->port());
  ASSERT_TRUE(steady.subscribed());
  // Handshake done, then silence: it never reads, so it never answers a ping.
  WsTestClient gone_quiet(server->port());
  ASSERT_TRUE(eventually([&] { return stats_of(*server, gone_quiet.local_port()).has_value(); }));
  EXPECT_TRUE(eventually([&] { return !stats_of(*server, gone_quiet.local_port()); })) << "the quiet client was kept";

  // Many idle periods later the reading client is still there and has every lap.
  ASSERT_TRUE(feed.wait_for_scans(feed.scan_times().size() + 25, 60s));
  const std::uint64_t last = feed.scan_times().back();
  steady.finish_at(last);
  expect_every_lap(steady, feed.scan_times(), last);
  EXPECT_TRUE(stats_of(*server, steady.local_port()).has_value()) << "the reading client was closed";
}

}  // namespace
}  // namespace ydscope::test
