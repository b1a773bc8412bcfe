#pragma once
// A Foxglove client of the app's Share, for the app tests: a port nobody listens on, and a client
// that keeps trying until the app serves (it starts sharing after its first frame).
#include <arpa/inet.h>
#include <netinet/in.h>
#include <sys/socket.h>
#include <unistd.h>

#include <chrono>
#include <memory>
#include <thread>

#include "support/ws_test_client.h"

namespace ydscope::test {

// A listening socket on 127.0.0.1 at a port the kernel chose; closed by the destructor.
struct Listener {
  int fd = ::socket(AF_INET, SOCK_STREAM, 0);
  std::uint16_t port = 0;
  Listener() {
    sockaddr_in address{};
    address.sin_family = AF_INET;
    address.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
    socklen_t length = sizeof address;
    if (::bind(fd, reinterpret_cast<sockaddr*>(&address), sizeof address) == 0 && ::listen(fd, 1) == 0 &&
        ::getsockname(fd, reinterpret_cast<sockaddr*>(&address), &length) == 0)
      port = ntohs(address.sin_port);
  }
  ~Listener() { ::close(fd); }
};

// A port nobody listens on now (there is a small window for another program to take it).
inline std::uint16_t free_port() { return Listener().port; }

// A client of the app's share, trying until `timeout` (the app starts sharing after its first frame).
inline std::unique_ptr<WsTestClient> connect_to(std::uint16_t port, std::chrono::seconds timeout) {
  const auto deadline = std::chrono::steady_clock::now() + timeout;
  while (std::chrono::steady_clock::now() < deadline) {
    try {
      return std::make_unique<WsTestClient>(port, 0, std::chrono::seconds(2));
    } catch (const std::exception&) {
      std::this_thread::sleep_for(std::chrono::milliseconds(200));
    }
  }
  return nullptr;
}

}  // namespace ydscope::test
