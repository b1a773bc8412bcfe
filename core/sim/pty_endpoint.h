#pragma once
// A pseudo-terminal the host opens like a serial port (posix_openpt, raw mode), optionally behind a
// symlink. The server does not hold the slave open: when the last host closes it, the master shows
// a hangup, and bytes are dropped instead of piling up for the next host (as a real closed port).
#include <string>

#include "core/sim/sim_endpoint.h"

namespace ydscope {

class PtyEndpoint final : public SimEndpoint {
 public:
  // Creates the pty and points `link` (when not empty) at its slave. Throws std::runtime_error.
  explicit PtyEndpoint(std::string link);
  ~PtyEndpoint() override;  // closes the pty, removes the link if it still points at it
  PtyEndpoint(const PtyEndpoint&) = delete;
  PtyEndpoint& operator=(const PtyEndpoint&) = delete;

  void poll_fds(std::vector<pollfd>& fds) override;
  void service(std::span<const pollfd> fds, std::vector<std::uint8_t>& host_bytes,
               SimServerCounters& counters) override;
  std::size_t send(std::span<const std::uint8_t> bytes) override;
  bool needs_recheck() const override { return hung_up_; }
  std::string device_path() const override { return slave_path_; }

  // Checks LINK can be used: absent, or a dangling symlink into /dev/pts (left by an earlier run).
  // Throws std::runtime_error with the sentence for the user otherwise.
  static void check_link_free(const std::string& link);

 private:
  void update_hangup(SimServerCounters* counters);

  int master_ = -1;
  std::string slave_path_;
  std::string link_;
  bool hung_up_ = false;
};

}  // namespace ydscope
