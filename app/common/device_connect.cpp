#include "app/common/device_connect.h"

#include <stdexcept>
#include <string>

namespace ydscope {

SessionSnapshot connect_and_wait(Session& session, const SessionConfig& config) {
  session.connect(config);
  const LinkState goal = config.scan ? LinkState::Scanning : LinkState::Ready;
  // A session that would reconnect reports its first failure too: the user is there to read it.
  const SessionSnapshot s = session.wait_until(
      [goal](const SessionSnapshot& x) {
        return x.state == goal || x.state == LinkState::Failed || x.state == LinkState::Reconnecting;
      },
      kConnectPatience);
  if (s.state == goal) return s;
  if (s.state == LinkState::Failed || s.state == LinkState::Reconnecting) throw std::runtime_error(s.message);
  throw std::runtime_error("gave up after " + std::to_string(kConnectPatience.count()) + " s waiting for " +
                           config.address + " (" + describe_snapshot(s) + ")");
}

}  // namespace ydscope
