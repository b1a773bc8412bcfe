#include "core/link/tcp_link.h"

#include <cerrno>
#include <cstring>

#include <boost/asio/connect.hpp>
#include <boost/asio/redirect_error.hpp>
#include <boost/asio/steady_timer.hpp>
#include <boost/asio/use_awaitable.hpp>
#include <boost/asio/write.hpp>

namespace ydscope {
namespace {

namespace asio = boost::asio;
using asio::ip::tcp;

std::string address_text(const std::string& host, std::uint16_t port) {
  const bool ipv6 = host.find(':') != std::string::npos;
  return "tcp://" + (ipv6 ? "[" + host + "]" : host) + ":" + std::to_string(port);
}

std::string connect_error(const std::string& where, int error, std::chrono::milliseconds timeout) {
  const std::string head = "cannot connect to " + where + ": ";
  switch (error) {
    case ECONNREFUSED: return head + "connection refused; is the bridge (e.g. ser2net) running on that port?";
    case ETIMEDOUT:
      return head + "no answer within " + std::to_string(timeout.count()) +
             " ms; check the host, the port and any firewall";
    case ENETUNREACH:
    case EHOSTUNREACH: return head + "host unreachable; check the address and the network";
    default: return head + std::strerror(error);
  }
}

}  // namespace

TcpLink::TcpLink(boost::asio::io_context& io, std::string host, std::uint16_t port)
    : socket_(io), host_(std::move(host)), port_(port) {}

// What the connect deadline cancels: the step in flight, if any. Shared with the timer's handler,
// which may run after the connecting coroutine has finished (and cleared these).
struct ConnectInFlight {
  tcp::resolver* resolver = nullptr;
  tcp::socket* socket = nullptr;
  bool expired = false;
};

asio::awaitable<std::unique_ptr<TcpLink>> TcpLink::connect(asio::io_context& io, std::string host, std::uint16_t port,
                                                           std::string& error, std::chrono::milliseconds timeout) {
  const std::string where = address_text(host, port);
  std::unique_ptr<TcpLink> link(new TcpLink(io, host, port));
  tcp::resolver resolver(io);
  auto in_flight = std::make_shared<ConnectInFlight>();
  asio::steady_timer deadline(io, timeout);
  deadline.async_wait([in_flight](const boost::system::error_code& ec) {
    if (ec) return;
    in_flight->expired = true;
    boost::system::error_code ignored;
    if (in_flight->resolver) in_flight->resolver->cancel();
    if (in_flight->socket) in_flight->socket->close(ignored);
  });
  struct Clear {  // on every way out, so a late deadline touches nothing of ours
    std::shared_ptr<ConnectInFlight> in_flight;
    asio::steady_timer& deadline;
    ~Clear() {
      in_flight->resolver = nullptr;
      in_flight->socket = nullptr;
      deadline.cancel();
    }
  } clear{in_flight, deadline};

  boost::system::error_code ec;
  in_flight->resolver = &resolver;
  const auto endpoints =
      co_await resolver.async_resolve(host, std::to_string(port), asio::redirect_error(asio::use_awaitable, ec));
  in_flight->resolver = nullptr;
  if (in_flight->expired) {
    error = connect_error(where, ETIMEDOUT, timeout);
    co_return nullptr;
  }
  if (ec || endpoints.empty()) {
    error = "cannot connect to " + where + ": unknown host '" + host + "'; check the name or use an IP address";
    co_return nullptr;
  }
  in_flight->socket = &link->socket_;
  co_await asio::async_connect(link->socket_, endpoints, asio::redirect_error(asio::use_awaitable, ec));
  if (in_flight->expired || ec) {
    error = connect_error(where, in_flight->expired ? ETIMEDOUT : ec.value(), timeout);
    co_return nullptr;
  }
  // Commands are two bytes and replies are awaited: do not let Nagle hold them back.
  link->socket_.set_option(tcp::no_delay(true), ec);
  co_return link;
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
