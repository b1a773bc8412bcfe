#include "core/link/tcp_link.h"

#include <poll.h>
#include <sys/socket.h>

#include <cerrno>
#include <cstring>

#include <boost/asio/write.hpp>

namespace ydscope {
namespace {

using Clock = std::chrono::steady_clock;

std::string address_text(const std::string& host, std::uint16_t port) {
  const bool ipv6 = host.find(':') != std::string::npos;
  return "tcp://" + (ipv6 ? "[" + host + "]" : host) + ":" + std::to_string(port);
}

// Non-blocking connect + poll, so a silent host costs at most the remaining time.
int connect_with_deadline(boost::asio::ip::tcp::socket& socket, const boost::asio::ip::tcp::endpoint& endpoint,
                          Clock::time_point deadline) {
  boost::system::error_code ec;
  socket.open(endpoint.protocol(), ec);
  if (ec) return ec.value();
  socket.native_non_blocking(true, ec);
  if (ec) return ec.value();
  const int fd = socket.native_handle();
  if (::connect(fd, endpoint.data(), static_cast<socklen_t>(endpoint.size())) == 0) return 0;
  if (errno != EINPROGRESS) return errno;
  for (;;) {
    const auto left = std::chrono::duration_cast<std::chrono::milliseconds>(deadline - Clock::now());
    if (left.count() <= 0) return ETIMEDOUT;
    pollfd pfd{fd, POLLOUT, 0};
    const int ready = ::poll(&pfd, 1, static_cast<int>(left.count()));
    if (ready < 0 && errno == EINTR) continue;
    if (ready < 0) return errno;
    if (ready == 0) return ETIMEDOUT;
    int so_error = 0;
    socklen_t len = sizeof so_error;
    if (::getsockopt(fd, SOL_SOCKET, SO_ERROR, &so_error, &len) != 0) return errno;
    return so_error;
  }
}

std::string connect_error(const std::string& where, int error, std::chrono::milliseconds timeout) {
  const std::string head = "cannot connect to " + where + ": ";
  switch (error) {
    case ECONNREFUSED:
      return head + "connection refused; is the bridge (e.g. ser2net) running on that port?";
    case ETIMEDOUT:
      return head + "no answer within " + std::to_string(timeout.count()) +
             " ms; check the host, the port and any firewall";
    case ENETUNREACH:
    case EHOSTUNREACH:
      return head + "host unreachable; check the address and the network";
    default:
      return head + std::strerror(error);
  }
}

}  // namespace

TcpLink::TcpLink(boost::asio::io_context& io, std::string host, std::uint16_t port)
    : socket_(io), host_(std::move(host)), port_(port) {}

std::unique_ptr<TcpLink> TcpLink::connect(boost::asio::io_context& io, const std::string& host,
                                          std::uint16_t port, std::string& error,
                                          std::chrono::milliseconds timeout) {
  const auto deadline = Clock::now() + timeout;
  const std::string where = address_text(host, port);
  boost::asio::ip::tcp::resolver resolver(io);
  boost::system::error_code ec;
  const auto endpoints = resolver.resolve(host, std::to_string(port), ec);
  if (ec || endpoints.empty()) {
    error = "cannot connect to " + where + ": unknown host '" + host + "'; check the name or use an IP address";
    return nullptr;
  }
  std::unique_ptr<TcpLink> link(new TcpLink(io, host, port));
  int last_error = ETIMEDOUT;
  for (const auto& entry : endpoints) {
    last_error = connect_with_deadline(link->socket_, entry.endpoint(), deadline);
    if (last_error == 0) break;
    link->socket_.close(ec);
    if (last_error == ETIMEDOUT) break;
  }
  if (last_error != 0) {
    error = connect_error(where, last_error, timeout);
    return nullptr;
  }
  // Commands are two bytes and replies are awaited: do not let Nagle hold them back.
  link->socket_.set_option(boost::asio::ip::tcp::no_delay(true), ec);
  return link;
}

void TcpLink::async_read_some(std::span<std::uint8_t> buffer, IoHandler handler) {
  socket_.async_read_some(boost::asio::buffer(buffer.data(), buffer.size()), std::move(handler));
}

void TcpLink::async_write(std::span<const std::uint8_t> bytes, IoHandler handler) {
  boost::asio::async_write(socket_, boost::asio::buffer(bytes.data(), bytes.size()), std::move(handler));
}

void TcpLink::close() {
  boost::system::error_code ignored;
  socket_.cancel(ignored);
  socket_.shutdown(boost::asio::ip::tcp::socket::shutdown_both, ignored);
  socket_.close(ignored);
}

bool TcpLink::set_baud(std::uint32_t /*baud*/, std::string& error) {
  error = describe() + " is a network bridge: set the baud in the bridge's configuration (e.g. ser2net)";
  return false;
}

std::string TcpLink::describe() const { return address_text(host_, port_); }

}  // namespace ydscope
