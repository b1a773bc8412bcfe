#include "app/cli/link_loss_notes.h"

#include <cstdio>

namespace ydscope::cli {

void LinkLossNotes::follow(const SessionSnapshot& s, bool tty) {
  const char* clear = tty ? "\r\033[K" : "";
  // An outage shorter than the time between two looks shows only in the reconnect count: said
  // all the same, as a loss and a return.
  const bool missed_outage = ever_scanned_ && !down_said_ && s.counters.reconnects > reconnects_seen_;
  reconnects_seen_ = s.counters.reconnects;
  if (scanning(s.state) && missed_outage) {
    ++losses_;
    std::fprintf(stderr, "%s%s: %s stopped: the link dropped and the session reconnected; %s\n", clear,
                 command_.c_str(), who_.c_str(), carry_on_.c_str());
    std::fprintf(stderr, "%s%s: %s is scanning again after less than a second%s%s\n", clear, command_.c_str(),
                 who_.c_str(), s.message.empty() ? "" : "; ", s.message.c_str());
    return;
  }
  if (scanning(s.state)) {
    if (down_said_) {
      const double gone_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - down_since_).count();
      std::fprintf(stderr, "%s%s: %s is scanning again after %.1f s%s%s\n", clear, command_.c_str(), who_.c_str(),
                   gone_s, s.message.empty() ? "" : "; ", s.message.c_str());
    }
    ever_scanned_ = true;
    down_said_ = false;
    return;
  }
  const bool trouble =
      s.state == LinkState::Stalled || s.state == LinkState::Reconnecting || s.state == LinkState::Failed;
  if (!trouble) return;
  if (!s.message.empty()) last_problem_ = s.message;
  if (down_said_) return;
  down_said_ = true;
  ++losses_;
  down_since_ = std::chrono::steady_clock::now();
  std::fprintf(stderr, "%s%s: %s %s: %s; %s\n", clear, command_.c_str(), who_.c_str(),
               ever_scanned_ ? "stopped" : "is not scanning",
               s.message.empty() ? std::string(link_state_name(s.state)).c_str() : s.message.c_str(),
               s.state == LinkState::Failed ? "it will not be retried" : carry_on_.c_str());
}

}  // namespace ydscope::cli
