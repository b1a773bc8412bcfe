#pragma once
// Says on stderr, once each, when a lidar stops scanning (and why) and when it scans again, with
// how long it was gone: every command that rides out link faults (record, scan) tells it alike.
#include <chrono>
#include <string>

#include "core/snapshot/session_snapshot.h"

namespace ydscope::cli {

class LinkLossNotes {
 public:
  // command: "ydscope-cli record"; who: "lidar0 (/dev/ttyUSB0)"; carry_on: what goes on meanwhile,
  // "the other lidars keep recording".
  LinkLossNotes(std::string command, std::string who, std::string carry_on)
      : command_(std::move(command)), who_(std::move(who)), carry_on_(std::move(carry_on)) {}

  // Call with each snapshot; `tty` clears a progress line first.
  void follow(const SessionSnapshot& s, bool tty);

  bool ever_scanned() const { return ever_scanned_; }
  bool down() const { return down_said_; }
  std::uint64_t losses() const { return losses_; }
  const std::string& last_problem() const { return last_problem_; }

 private:
  std::string command_, who_, carry_on_;
  bool ever_scanned_ = false;
  bool down_said_ = false;  // its stop was said; its return will be
  std::uint64_t losses_ = 0;
  std::uint64_t reconnects_seen_ = 0;  // the session's count at the last look
  std::chrono::steady_clock::time_point down_since_;
  std::string last_problem_;
};

// True while laps flow (a command may briefly interrupt them).
constexpr bool scanning(LinkState state) {
  return state == LinkState::Scanning || state == LinkState::CommandInProgress;
}

}  // namespace ydscope::cli
