// TcpLink against a listener on 127.0.0.1 (an ephemeral port), as a ser2net bridge would be.
#include <array>
#include <utility>  // before asio's awaitable.hpp, which uses std::exchange without including it
#include <chrono>
#include <thread>
#include <vector>

#include <boost/asio/co_spawn.hpp>
#include <boost/asio/read.hpp>
#include <boost/asio/steady_timer.hpp>
#include <boost/asio/write.hpp>
#include <gtest/gtest.h>

#include "core/link/tcp_link.h"
#include "link/await_support.h"
#include "link/link_read_support.h"

namespace ydscope {
namespace {

using boost::asio::ip::tcp;
constexpr auto kTcpHangGuard = std::chrono::seconds(5);

TEST(TcpLink, ConnectsAndCarriesBytesBothWays) {
  boost::asio::io_context io;
  tcp::acceptor acceptor(io, tcp::endpoint(boost::asio::ip::make_address("127.0.0.1"), 0));
  const auto port = acceptor.local_endpoint().port();

  // The bridge accepts on its own thread while the link connects on `io`.
  boost::asio::io_context bridge_io;
  tcp::socket bridge(bridge_io);
  std::thread accept_thread([&] { acceptor.accept(bridge); });
  std::string error;
  auto link = test::run_awaitable(io, TcpLink::connect(io, "127.0.0.1", port, error));
  accept_thread.join();
  ASSERT_TRUE(link) << error;
  EXPECT_EQ(link->describe(), "tcp://127.0.0.1:" + std::to_string(port));
  EXPECT_TRUE(link->accepts_commands());

  const std::vector<std::uint8_t> device_bytes{0xA5, 0x5A, 0x05, 0x00, 0x00, 0x40, 0x81, 0xAA, 0x55};
  boost::asio::write(bridge, boost::asio::buffer(device_bytes));
  const auto received = test::read_from_link(io, *link, device_bytes.size(), 4, kTcpHangGuard);
  EXPECT_FALSE(received.end) << received.end.message();
  EXPECT_EQ(received.bytes, device_bytes);

  const std::array<std::uint8_t, 2> stop{0xA5, 0x65};
  bool written = false;
  link->async_write(stop, [&](const boost::system::error_code& ec, std::size_t n) {
    EXPECT_FALSE(ec);
    EXPECT_EQ(n, 2u);
    written = true;
  });
  io.restart();
  io.run_for(kTcpHangGuard);
  ASSERT_TRUE(written);
  std::array<std::uint8_t, 2> at_bridge{};
  boost::asio::read(bridge, boost::asio::buffer(at_bridge));
  EXPECT_EQ(at_bridge, stop);

  // The bridge hanging up is end-of-file for the session (it reconnects).
  bridge.close();
  const auto after_hang_up = test::read_from_link(io, *link, SIZE_MAX, 4, kTcpHangGuard);
  EXPECT_TRUE(after_hang_up.bytes.empty());
  EXPECT_EQ(after_hang_up.end, boost::asio::error::eof);
}

TEST(TcpLink, RefusedConnectionIsOneSentence) {
  boost::asio::io_context io;
  std::uint16_t port = 0;
  {  // A port that was just free: nothing listens there now.
    tcp::acceptor probe(io, tcp::endpoint(boost::asio::ip::make_address("127.0.0.1"), 0));
    port = probe.local_endpoint().port();
  }
  std::string error;
  EXPECT_FALSE(test::run_awaitable(io, TcpLink::connect(io, "127.0.0.1", port, error)));
  EXPECT_EQ(error, "cannot connect to tcp://127.0.0.1:" + std::to_string(port) +
                       ": connection refused; is the bridge (e.g. ser2net) running on that port?");
}

// A listener that never accepts: once its accept queue is full the kernel drops further SYNs,
// so a connect never completes and must give up at its timeout.
class SilentListener {
 public:
  explicit SilentListener(boost::asio::io_context& io) : io_(io), acceptor_(io) {
    acceptor_.open(tcp::v4());
    acceptor_.bind(tcp::endpoint(boost::asio::ip::make_address("127.0.0.1"), 0));
    acceptor_.listen(0);
  }
  std::uint16_t port() const { return acceptor_.local_endpoint().port(); }
  // Connects (300 ms timeout each) until one is not answered; false if all 16 were. `error` holds
  // the unanswered connect's sentence.
  bool fill_accept_queue(std::string& error) {
    for (int i = 0; i < 16; ++i) {
      auto link =
          test::run_awaitable(io_, TcpLink::connect(io_, "127.0.0.1", port(), error, std::chrono::milliseconds(300)));
      if (!link) return true;
      queued_.push_back(std::move(link));
    }
    return false;
  }

 private:
  boost::asio::io_context& io_;
  tcp::acceptor acceptor_;
  std::vector<std::unique_ptr<TcpLink>> queued_;
};

TEST(TcpLink, SilentListenerTimesOut) {
  boost::asio::io_context io;
  SilentListener listener(io);
  const auto port = listener.port();
  std::string error;
  EXPECT_TRUE(listener.fill_accept_queue(error)) << "the listener never stopped answering";
  EXPECT_EQ(error, "cannot connect to tcp://127.0.0.1:" + std::to_string(port) +
                       ": no answer within 300 ms; check the host, the port and any firewall");
}

TEST(TcpLink, AConnectThatWaitsLeavesTheIoContextFreeForOtherWork) {
  // The session's I/O thread runs its timers and requests while a bridge keeps it waiting.
  boost::asio::io_context io;
  SilentListener listener(io);
  const auto port = listener.port();
  std::string error;
  ASSERT_TRUE(listener.fill_accept_queue(error));

  bool connect_done = false;
  bool timer_fired_while_connecting = false;
  boost::asio::co_spawn(io, TcpLink::connect(io, "127.0.0.1", port, error, std::chrono::milliseconds(1000)),
                        [&](std::exception_ptr, std::unique_ptr<TcpLink>) { connect_done = true; });
  boost::asio::steady_timer other_work(io, std::chrono::milliseconds(20));
  other_work.async_wait([&](const boost::system::error_code&) { timer_fired_while_connecting = !connect_done; });
  io.restart();
  io.run_for(kTcpHangGuard);
  EXPECT_TRUE(connect_done);
  EXPECT_TRUE(timer_fired_while_connecting);
  EXPECT_NE(error.find("no answer within 1000 ms"), std::string::npos) << error;
}

TEST(TcpLink, UnknownHostIsOneSentence) {
  boost::asio::io_context io;
  std::string error;
  EXPECT_FALSE(test::run_awaitable(
      io, TcpLink::connect(io, "no-such-host.invalid", 2000, error, std::chrono::milliseconds(2000))));
  EXPECT_NE(error.find("unknown host 'no-such-host.invalid'"), std::string::npos) << error;
}

TEST(TcpLink, BaudBelongsToTheBridge) {
  boost::asio::io_context io;
  tcp::acceptor acceptor(io, tcp::endpoint(boost::asio::ip::make_address("127.0.0.1"), 0));
  std::string error;
  auto link = test::run_awaitable(io, TcpLink::connect(io, "127.0.0.1", acceptor.local_endpoint().port(), error));
  ASSERT_TRUE(link) << error;  // the kernel completes the handshake from the backlog
  EXPECT_FALSE(link->set_baud(512000, error));
  EXPECT_NE(error.find("ser2net"), std::string::npos) << error;
}

}  // namespace
}  // namespace ydscope
