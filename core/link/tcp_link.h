#pragma once
// ByteLink over TCP, for serial-to-network bridges such as ser2net (tcp://host:port). The bridge
// owns the line rate, so set_baud is refused with a sentence saying so.
#include <chrono>
#include <cstdint>
#include <memory>
#include <string>
#include <utility>  // before asio's awaitable.hpp, which uses std::exchange without including it

#include <boost/asio/awaitable.hpp>
#include <boost/asio/io_context.hpp>
#include <boost/asio/ip/tcp.hpp>

#include "core/link/byte_link.h"

namespace ydscope {

class TcpLink final : public ByteLink {
 public:
  static constexpr std::chrono::milliseconds kDefaultConnectTimeout{3000};

  // Resolves and connects on `io`, at most `timeout` in total, without blocking its thread (a
  // silent host must not stall the session's other work). On failure gives null and sets `error`
  // (which must outlive the wait) to one sentence.
  static boost::asio::awaitable<std::unique_ptr<TcpLink>> connect(
      boost::asio::io_context& io, std::string host, std::uint16_t port, std::string& error,
      std::chrono::milliseconds timeout = kDefaultConnectTimeout);

  void async_read_some(std::span<std::uint8_t> buffer, IoHandler handler) override;
  void async_write(std::span<const std::uint8_t> bytes, IoHandler handler) override;
  void close() override;
  bool set_baud(std::uint32_t baud, std::string& error) override;
  bool accepts_commands() const override { return true; }
  std::string describe() const override;

 private:
  TcpLink(boost::asio::io_context& io, std::string host, std::uint16_t port);

  boost::asio::ip::tcp::socket socket_;
  std::string host_;
  std::uint16_t port_;
};

}  // namespace ydscope
