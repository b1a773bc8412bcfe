// A lidar that streams at one baud while the host listens at another: a real serial line garbles
// every byte both ways, so the device never answers and the session must say why in one sentence
// ("try --baud ..."), not "no reply" alone. A pseudo-terminal passes bytes through whatever the
// baud, so the line here runs every byte through a UART model at the two bauds.
#include <gtest/gtest.h>

#include <deque>
#include <memory>

#include "core/link/serial_link.h"
#include "sim/host_port.h"
#include "support/session_test_support.h"
#include "support/uart_line.h"

namespace ydscope {
namespace {

using namespace test;

class WrongBaudLine final : public ByteLink {
 public:
  WrongBaudLine(std::unique_ptr<ByteLink> inner, std::uint32_t device_baud, std::uint32_t host_baud)
      : inner_(std::move(inner)), device_baud_(device_baud), host_baud_(host_baud) {}

  void async_read_some(std::span<std::uint8_t> buffer, IoHandler handler) override {
    if (!pending_.empty()) return hand_out(buffer, handler, {});
    inner_->async_read_some(buffer, [this, buffer, handler](const boost::system::error_code& ec, std::size_t n) {
      const std::vector<std::uint8_t> sent(buffer.begin(), buffer.begin() + static_cast<std::ptrdiff_t>(n));
      const auto heard = host_baud_ == device_baud_ ? sent : resample_uart(sent, device_baud_, host_baud_);
      pending_.insert(pending_.end(), heard.begin(), heard.end());
      if (pending_.empty() && !ec) return async_read_some(buffer, handler);  // all lost: read on
      hand_out(buffer, handler, ec);
    });
  }
  void async_write(std::span<const std::uint8_t> bytes, IoHandler handler) override {
    const std::vector<std::uint8_t> sent(bytes.begin(), bytes.end());
    written_ = std::make_shared<std::vector<std::uint8_t>>(
        host_baud_ == device_baud_ ? sent : resample_uart(sent, host_baud_, device_baud_));
    inner_->async_write(*written_, [keep = written_, handler, n = bytes.size()](const boost::system::error_code& ec,
                                                                                std::size_t) { handler(ec, n); });
  }
  void close() override { inner_->close(); }
  double line_bytes_per_s() const override { return host_baud_ / 10.0; }
  bool set_baud(std::uint32_t baud, std::string& error) override {
    host_baud_ = baud;
    return inner_->set_baud(baud, error);
  }
  bool accepts_commands() const override { return true; }
  std::string describe() const override { return inner_->describe(); }

 private:
  void hand_out(std::span<std::uint8_t> buffer, const IoHandler& handler, const boost::system::error_code& ec) {
    const std::size_t n = std::min(buffer.size(), pending_.size());
    std::copy_n(pending_.begin(), n, buffer.begin());
    pending_.erase(pending_.begin(), pending_.begin() + static_cast<std::ptrdiff_t>(n));
    handler(ec, n);
  }

  std::unique_ptr<ByteLink> inner_;
  std::uint32_t device_baud_;
  std::uint32_t host_baud_;  // I/O thread only
  std::deque<std::uint8_t> pending_;
  std::shared_ptr<std::vector<std::uint8_t>> written_;
};

// The virtual lidar left scanning by an earlier host, as a unit that streams on power-up does.
void leave_scanning(const std::string& port) {
  HostPort host;
  ASSERT_TRUE(host.open_device(port));
  ASSERT_TRUE(host.send({0xA5, 0x60}));
  host.read(2000, std::chrono::seconds(2));
  host.close();
}

SessionConfig wrong_baud_config(const std::string& port, std::uint32_t device_baud, std::uint32_t host_baud) {
  SessionConfig config = config_for(port, std::nullopt);
  config.baud = host_baud;
  config.reconnect = false;
  config.open_link = [port, device_baud](boost::asio::io_context& io, std::uint32_t baud,
                                         std::string& error) -> std::unique_ptr<ByteLink> {
    auto serial = SerialLink::open(io, port, baud, error);
    if (!serial) return nullptr;
    return std::make_unique<WrongBaudLine>(std::move(serial), device_baud, baud);
  };
  return config;
}

TEST(WrongBaud, AStreamingG6HeardAt230400IsSaidToBeAtAnotherBaud) {
  SimOnPty sim(Model::G6);
  leave_scanning(sim.port());
  Session session;
  session.connect(wrong_baud_config(sim.port(), 512000, 230400));
  const SessionSnapshot s = wait_for_state(session, LinkState::Failed);
  ASSERT_EQ(s.state, LinkState::Failed) << s.message;
  EXPECT_NE(s.message.find("no device-info reply (A5 90)"), std::string::npos) << s.message;
  EXPECT_NE(s.message.find("looks like another baud"), std::string::npos) << s.message;
  EXPECT_NE(s.message.find("512000"), std::string::npos) << "the baud to try: " << s.message;
}

TEST(WrongBaud, ProbingBaudsFindsTheStreamingG6) {
  SimOnPty sim(Model::G6);
  leave_scanning(sim.port());
  Session session;
  SessionConfig config = wrong_baud_config(sim.port(), 512000, 230400);
  config.probe_baud = true;  // --baud auto: 230400 first, then 512000
  session.connect(config);
  ASSERT_EQ(take_laps(session, 2), 2u) << session.snapshot().message;
  EXPECT_EQ(session.snapshot().baud, 512000u);
}

}  // namespace
}  // namespace ydscope
