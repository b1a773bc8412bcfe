#pragma once
// Where SimServer's thread meets a host: a pseudo-terminal or a TCP port. Only the server thread
// touches an endpoint. Bytes for a host that is not there are lost, as on a real line.
#include <poll.h>

#include <cstddef>
#include <cstdint>
#include <span>
#include <string>
#include <vector>

namespace ydscope {

struct SimServerCounters;

class SimEndpoint {
 public:
  virtual ~SimEndpoint() = default;
  // Appends the descriptors to wait on for reading (host bytes, a host connecting).
  virtual void poll_fds(std::vector<pollfd>& fds) = 0;
  // After the wait: handles the descriptors poll_fds added (same order), appending host bytes.
  virtual void service(std::span<const pollfd> fds, std::vector<std::uint8_t>& host_bytes,
                       SimServerCounters& counters) = 0;
  // Hands device bytes to the host; returns how many a host can read (the rest are lost).
  virtual std::size_t send(std::span<const std::uint8_t> bytes) = 0;
  // True while the endpoint cannot be woken by a host appearing and must be re-checked soon.
  virtual bool needs_recheck() const = 0;
  virtual std::string device_path() const = 0;
};

}  // namespace ydscope
