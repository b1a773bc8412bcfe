#pragma once
// Where a Session's I/O thread posts what it knows for every other thread: the parts of a
// SessionSnapshot that change by event (state, device, health, set values, the last command's
// outcome), written under a lock, with a wake-up for whoever waits on them. The live counters are
// not posted here: they are atomics the reader adds when it takes a snapshot.
#include <chrono>
#include <condition_variable>
#include <functional>
#include <mutex>

#include "core/snapshot/session_snapshot.h"

namespace ydscope {

class SnapshotBoard {
 public:
  // I/O thread: changes the posted snapshot and wakes the waiters.
  void publish(const std::function<void(SessionSnapshot&)>& change);
  void set_state(LinkState state, std::string message);
  // The outcome of a command: posted as the last result (and the session no longer busy), then
  // handed to its caller, whose exceptions stop here.
  void post_result(const CommandResult& result, const CommandCallback& done);
  LinkState state() const;
  // Any thread: a copy of what is posted.
  SessionSnapshot read() const;
  // Any thread: blocks until `done(take())` holds or the timeout passes, and returns the last
  // snapshot taken. It looks again at every post, and every 20 ms for the counters, which change
  // without one.
  SessionSnapshot wait_until(const std::function<SessionSnapshot()>& take,
                             const std::function<bool(const SessionSnapshot&)>& done,
                             std::chrono::milliseconds timeout) const;

 private:
  mutable std::mutex mutex_;
  mutable std::condition_variable changed_;
  SessionSnapshot posted_;
};

}  // namespace ydscope
