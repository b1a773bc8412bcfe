#include "core/session/snapshot_board.h"

#include <algorithm>

namespace ydscope {

using namespace std::chrono_literals;

void SnapshotBoard::publish(const std::function<void(SessionSnapshot&)>& change) {
  {
    std::lock_guard lock(mutex_);
    change(posted_);
  }
  changed_.notify_all();
}

void SnapshotBoard::set_state(LinkState state, std::string message) {
  publish([&](SessionSnapshot& s) {
    s.state = state;
    s.message = std::move(message);
  });
}

void SnapshotBoard::post_result(const CommandResult& result, const CommandCallback& done) {
  publish([&](SessionSnapshot& s) {
    s.last_result = result;
    s.busy = false;
    s.busy_what.clear();
  });
  if (!done) return;
  try {
    done(result);
  } catch (...) {
    // A caller's callback must not take the I/O thread down.
  }
}

LinkState SnapshotBoard::state() const {
  std::lock_guard lock(mutex_);
  return posted_.state;
}

SessionSnapshot SnapshotBoard::read() const {
  std::lock_guard lock(mutex_);
  return posted_;
}

SessionSnapshot SnapshotBoard::wait_until(const std::function<SessionSnapshot()>& take,
                                          const std::function<bool(const SessionSnapshot&)>& done,
                                          std::chrono::milliseconds timeout) const {
  const auto deadline = std::chrono::steady_clock::now() + timeout;
  for (;;) {
    SessionSnapshot s = take();
    if (done(s) || std::chrono::steady_clock::now() >= deadline) return s;
    std::unique_lock lock(mutex_);
    changed_.wait_until(lock, std::min(deadline, std::chrono::steady_clock::now() + 20ms));
  }
}

}  // namespace ydscope
