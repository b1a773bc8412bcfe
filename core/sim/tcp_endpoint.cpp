#include "core/sim/tcp_endpoint.h"

#include <arpa/inet.h>
#include <fcntl.h>
#include <netinet/in.h>
#include <netinet/tcp.h>
#include <sys/socket.h>
#include <unistd.h>

#include <array>
#include <cerrno>
#include <cstring>
#include <stdexcept>

#include "core/sim/sim_server.h"

namespace ydscope {

TcpEndpoint::TcpEndpoint(const std::string& host, std::uint16_t port) : host_(host) {
  sockaddr_in address{};
  address.sin_family = AF_INET;
  address.sin_port = htons(port);
  if (::inet_pton(AF_INET, host.c_str(), &address.sin_addr) != 1)
    throw std::runtime_error("'" + host + "' is not an IPv4 address to listen on (try 127.0.0.1)");
  listener_ = ::socket(AF_INET, SOCK_STREAM | SOCK_NONBLOCK | SOCK_CLOEXEC, 0);
  if (listener_ < 0) throw std::runtime_error(std::string("could not create a TCP socket: ") + std::strerror(errno));
  const int one = 1;
  ::setsockopt(listener_, SOL_SOCKET, SO_REUSEADDR, &one, sizeof one);
  if (::bind(listener_, reinterpret_cast<const sockaddr*>(&address), sizeof address) != 0 ||
      ::listen(listener_, 4) != 0) {
    const int error = errno;
    ::close(listener_);
    throw std::runtime_error("could not listen on " + host + ":" + std::to_string(port) + ": " + std::strerror(error) +
                             (error == EADDRINUSE ? " (another program uses the port; pick another)" : ""));
  }
  socklen_t size = sizeof address;
  ::getsockname(listener_, reinterpret_cast<sockaddr*>(&address), &size);
  port_ = ntohs(address.sin_port);
}

TcpEndpoint::~TcpEndpoint() {
  if (client_ >= 0) ::close(client_);
  if (listener_ >= 0) ::close(listener_);
}

std::string TcpEndpoint::device_path() const { return "tcp://" + host_ + ":" + std::to_string(port_); }

void TcpEndpoint::poll_fds(std::vector<pollfd>& fds) {
  fds.push_back({listener_, POLLIN, 0});
  fds.push_back({client_, POLLIN, 0});
}

void TcpEndpoint::service(std::span<const pollfd> fds, std::vector<std::uint8_t>& host_bytes,
                          SimServerCounters& counters) {
  if (fds.size() >= 1 && (fds[0].revents & POLLIN)) {
    for (;;) {
      const int fd = ::accept4(listener_, nullptr, nullptr, SOCK_NONBLOCK | SOCK_CLOEXEC);
      if (fd < 0) break;
      if (client_ >= 0) {
        ++counters.rejected_hosts;
        ::close(fd);
        continue;
      }
      const int one = 1;
      ::setsockopt(fd, IPPROTO_TCP, TCP_NODELAY, &one, sizeof one);
      client_ = fd;
      ++counters.host_connections;
    }
  }
  if (client_ >= 0 && fds.size() >= 2 && (fds[1].revents & (POLLIN | POLLHUP | POLLERR))) {
    std::array<std::uint8_t, 512> buffer{};
    for (;;) {
      const ssize_t n = ::recv(client_, buffer.data(), buffer.size(), 0);
      if (n > 0) {
        host_bytes.insert(host_bytes.end(), buffer.begin(), buffer.begin() + n);
        continue;
      }
      if (n == 0 || (errno != EAGAIN && errno != EWOULDBLOCK && errno != EINTR)) {
        ::close(client_);  // the host went away; the next one may connect
        client_ = -1;
      }
      break;
    }
  }
}

std::size_t TcpEndpoint::send(std::span<const std::uint8_t> bytes) {
  if (client_ < 0) return 0;
  std::size_t sent = 0;
  while (sent < bytes.size()) {
    const ssize_t n = ::send(client_, bytes.data() + sent, bytes.size() - sent, MSG_NOSIGNAL);
    if (n > 0) {
      sent += static_cast<std::size_t>(n);
    } else if (n < 0 && errno == EINTR) {
      continue;
    } else {
      break;
    }
  }
  return sent;
}

}  // namespace ydscope
