#pragma once
// A bare POSIX host for the server tests: opens a device path or connects to TCP, raw mode, and
// reads with poll until a count, a deadline or a silence. Deliberately not the link layer's code.
#include <arpa/inet.h>
#include <fcntl.h>
#include <netinet/in.h>
#include <poll.h>
#include <sys/socket.h>
#include <termios.h>
#include <unistd.h>

#include <chrono>
#include <cstdint>
#include <string>
#include <vector>

namespace ydscope::test {

using Clock = std::chrono::steady_clock;

class HostPort {
 public:
  HostPort() = default;
  ~HostPort() { close(); }
  HostPort(const HostPort&) = delete;
  HostPort& operator=(const HostPort&) = delete;

  bool open_device(const std::string& path) {
    fd_ = ::open(path.c_str(), O_RDWR | O_NOCTTY | O_NONBLOCK);
    if (fd_ < 0) return false;
    termios tio{};
    ::tcgetattr(fd_, &tio);
    ::cfmakeraw(&tio);
    ::tcsetattr(fd_, TCSANOW, &tio);
    return true;
  }

  bool connect_tcp(std::uint16_t port) {
    fd_ = ::socket(AF_INET, SOCK_STREAM, 0);
    socket_ = true;
    eof_ = false;
    sockaddr_in address{};
    address.sin_family = AF_INET;
    address.sin_port = htons(port);
    address.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
    if (::connect(fd_, reinterpret_cast<const sockaddr*>(&address), sizeof address) != 0) return false;
    ::fcntl(fd_, F_SETFL, ::fcntl(fd_, F_GETFL) | O_NONBLOCK);
    return true;
  }

  void close() {
    if (fd_ >= 0) ::close(fd_);
    fd_ = -1;
  }

  bool send(std::vector<std::uint8_t> bytes) {
    // MSG_NOSIGNAL: a server that turned us away must fail the send, not kill the test with SIGPIPE.
    const ssize_t n =
        socket_ ? ::send(fd_, bytes.data(), bytes.size(), MSG_NOSIGNAL) : ::write(fd_, bytes.data(), bytes.size());
    return n == static_cast<ssize_t>(bytes.size());
  }

  // Reads until `count` bytes arrived or `timeout` passed. eof is set when the other side is gone.
  std::vector<std::uint8_t> read(std::size_t count, std::chrono::milliseconds timeout) {
    std::vector<std::uint8_t> out;
    const auto end = Clock::now() + timeout;
    while (out.size() < count && Clock::now() < end) {
      if (!wait_readable(end)) break;
      if (!read_some(out)) break;
    }
    return out;
  }

  // Reads until nothing came for `silence` (or `limit` passed); last_byte_at is when the last byte came.
  std::vector<std::uint8_t> read_until_silence(std::chrono::milliseconds silence, std::chrono::milliseconds limit,
                                               Clock::time_point& last_byte_at) {
    std::vector<std::uint8_t> out;
    const auto end = Clock::now() + limit;
    last_byte_at = Clock::now();
    while (Clock::now() < end) {
      if (!wait_readable(std::min(end, Clock::now() + silence))) break;
      const std::size_t before = out.size();
      if (!read_some(out)) break;
      if (out.size() > before) last_byte_at = Clock::now();
    }
    return out;
  }

  bool eof() const { return eof_; }

 private:
  bool wait_readable(Clock::time_point until) {
    const auto left = std::chrono::duration_cast<std::chrono::milliseconds>(until - Clock::now()).count();
    pollfd p{fd_, POLLIN, 0};
    return ::poll(&p, 1, static_cast<int>(std::max<long long>(0, left))) > 0;
  }
  bool read_some(std::vector<std::uint8_t>& out) {
    std::uint8_t buffer[4096];
    const ssize_t n = ::read(fd_, buffer, sizeof buffer);
    if (n > 0) {
      out.insert(out.end(), buffer, buffer + n);
      return true;
    }
    eof_ = true;  // 0 (closed) or an error such as EIO (the pty went away)
    return false;
  }

  int fd_ = -1;
  bool socket_ = false;
  bool eof_ = false;
};

}  // namespace ydscope::test
