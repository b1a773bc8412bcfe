#pragma once
// The intents a user sends a connected Session (the scan or ranging frequency, power-down
// protection, a health read): queued on the I/O thread and run one at a time as the manuals
// require while a device scans: stop, command, read back, resume (the CommandSequencer's steps).
// Each outcome is posted on the board and handed to its caller. I/O thread only.
#include <deque>
#include <functional>
#include <string>
#include <utility>  // before asio's awaitable.hpp, which uses std::exchange without including it

#include <boost/asio/awaitable.hpp>

#include "core/session/command_sequencer.h"
#include "core/session/device_settings.h"
#include "core/session/running_scan.h"
#include "core/session/session_io.h"
#include "core/session/snapshot_board.h"

namespace ydscope {

struct SessionIntent {
  enum class Kind { ScanHz, RangingKhz, PowerDown, Health } kind;
  double hz = 0;
  std::uint16_t khz = 0;
  bool on = false;
  CommandCallback done;
};

// "set scan frequency to 10.0 Hz": what an intent does, for its result and the busy line.
std::string intent_text(const SessionIntent& intent);

class IntentRunner {
 public:
  struct Parts {
    SessionIo& link;
    CommandSequencer& sequencer;
    SnapshotBoard& board;
    RunningScan& scan;
    std::function<void()> restart_decoder;  // the lap a stop cut short is not a lap
    std::function<void()> record_metadata;  // a setting changed: tell whatever captures
  };
  explicit IntentRunner(Parts parts) : parts_(std::move(parts)) {}

  void push(SessionIntent intent) { queue_.push_back(std::move(intent)); }
  bool pending() const { return !queue_.empty(); }
  // Runs the oldest intent against the connected device, whose model is `profile`.
  boost::asio::awaitable<void> run_next(const ModelProfile* profile);
  // Ends every queued intent unrun, saying why.
  void fail_all(const std::string& why);

  // What the user last set successfully: start-up puts it back after a reconnect.
  const DeviceSettings& settings() const { return settings_; }
  // Another device: its settings are not the last one's.
  void forget_settings() { settings_ = {}; }
  // While power-down protection is on, the scan needs A5 60 as a keep-alive.
  bool power_down_wanted() const { return settings_.power_down_protection.value_or(false); }

 private:
  // The command and its read-back. Its references are run_next's locals, which it awaits at once.
  boost::asio::awaitable<void> run(const SessionIntent& intent, const ModelProfile& profile, CommandResult& result,
                                   bool& lost);

  Parts parts_;
  std::deque<SessionIntent> queue_;
  DeviceSettings settings_;
};

}  // namespace ydscope
