#pragma once
// A TCP port the host connects to, as to a ser2net bridge. One host at a time: a second host is
// accepted and closed at once (counted). Loopback unless told otherwise.
#include <cstdint>
#include <string>

#include "core/sim/sim_endpoint.h"

namespace ydscope {

class TcpEndpoint final : public SimEndpoint {
 public:
  // Listens on host:port (port 0: any free port). Throws std::runtime_error (address in use, ...).
  TcpEndpoint(const std::string& host, std::uint16_t port);
  ~TcpEndpoint() override;
  TcpEndpoint(const TcpEndpoint&) = delete;
  TcpEndpoint& operator=(const TcpEndpoint&) = delete;

  void poll_fds(std::vector<pollfd>& fds) override;
  void service(std::span<const pollfd> fds, std::vector<std::uint8_t>& host_bytes,
               SimServerCounters& counters) override;
  std::size_t send(std::span<const std::uint8_t> bytes) override;
  bool needs_recheck() const override { return false; }
  std::string device_path() const override;
  std::uint16_t port() const { return port_; }

 private:
  int listener_ = -1;
  int client_ = -1;
  std::string host_;
  std::uint16_t port_ = 0;
};

}  // namespace ydscope
