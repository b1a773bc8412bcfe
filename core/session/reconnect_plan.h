#pragma once
// How a session waits before it reopens its link after a fault. The wait doubles from
// first_backoff up to max_backoff and starts over after a good start. A serial port's return is
// watched (PortWatch), so for it the timer is only the fallback; a TCP bridge cannot be watched,
// so its wait stays short enough that a restarted bridge is used again within a second.
#include <algorithm>
#include <chrono>
#include <optional>
#include <string>

#include "core/session/session.h"

namespace ydscope {

class ReconnectPlan {
 public:
  static constexpr std::chrono::milliseconds kMaxTcpBackoff{750};

  explicit ReconnectPlan(const SessionConfig& config);

  std::chrono::milliseconds delay() const { return delay_; }
  void waited() { delay_ = std::min(delay_ * 2, max_); }  // another try failed, or is about to be made
  void started() { delay_ = first_; }                     // the device is up again
  // The serial device path whose return ends the wait; none for TCP or a test's own opener.
  const std::optional<std::string>& watched_path() const { return watched_path_; }
  // What the state line adds to the error: "; retrying when /dev/ttyUSB0 comes back, or in 0.5 s".
  std::string retry_text(bool watching) const;
  // True when waiting cannot help: the serial path exists and is no device (a regular file, a
  // folder), so no plugging in will make it a port.
  bool hopeless() const;

 private:
  std::chrono::milliseconds first_, max_, delay_;
  std::optional<std::string> watched_path_;
};

}  // namespace ydscope
