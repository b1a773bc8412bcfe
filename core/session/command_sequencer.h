#pragma once
// CommandSequencer: the manuals' command discipline as coroutines over SessionIo. A command is sent
// only with the device stopped (pause_scan: A5 65, drain), awaited with a timeout and retried a
// bounded number of times; targets are reached by stepping and verified by read-back. Each step
// returns a value or one sentence saying what failed. I/O thread only.
#include <chrono>
#include <cstdint>
#include <optional>
#include <string>
#include <utility>  // before asio's awaitable.hpp, which uses std::exchange without including it

#include <boost/asio/awaitable.hpp>

#include "core/session/session_io.h"
#include "core/snapshot/session_snapshot.h"
#include "core/protocol/commands.h"
#include "core/protocol/model_profile.h"
#include "core/protocol/reply.h"

namespace ydscope {

template <class T>
struct Step {
  std::optional<T> value;
  std::string error;       // set when value is empty
  bool link_lost = false;  // the link died: the supervisor reconnects rather than reporting
  bool ok() const { return value.has_value() && error.empty(); }
};

// A step that failed because a step it waited on failed: that one's sentence and link loss.
template <class T, class Cause>
Step<T> failure_of(const Step<Cause>& cause) {
  Step<T> step;
  step.error = cause.error;
  step.link_lost = cause.link_lost;
  return step;
}

class CommandSequencer {
 public:
  // Bounds on the stepping loops, so a device that never reaches a target cannot hold the thread.
  static constexpr int kMaxScanHzSteps = 200;
  static constexpr std::chrono::milliseconds kDrainQuiet{40};
  static constexpr std::chrono::milliseconds kDrainLimit{1500};

  explicit CommandSequencer(SessionIo& io) : io_(io) {}
  void configure(std::chrono::milliseconds reply_timeout, int attempts);
  // A new device: forget which health command worked.
  void reset_device() { health_command_.reset(); }

  // A5 65 then drain when the device streams (or may: `force` after connecting). True when it was scanning.
  boost::asio::awaitable<bool> pause_scan(bool force = false);
  // A5 60 again (with the stream routed to the decoder) when `was_scanning`. False if it could not be sent.
  bool resume_scan(bool was_scanning);

  // One command with retries; the device must not be scanning.
  boost::asio::awaitable<Step<Exchange>> command(Command command);

  boost::asio::awaitable<Step<DeviceInfo>> device_info();
  // The model's health command first (or the one that worked before), then the other one once.
  boost::asio::awaitable<Step<HealthReport>> health(const ModelProfile& profile);
  boost::asio::awaitable<Step<double>> scan_hz();
  boost::asio::awaitable<Step<double>> step_scan_hz(const ModelProfile& profile, double target_hz);
  boost::asio::awaitable<Step<std::uint16_t>> ranging_khz(const ModelProfile& profile);
  boost::asio::awaitable<Step<std::uint16_t>> cycle_ranging_to(const ModelProfile& profile, std::uint16_t target_khz);
  // A5 D9 toggles; toggles again when the answer is not `on`. Value: the state the device reports.
  boost::asio::awaitable<Step<bool>> power_down_protection(bool on);

 private:
  std::string link_text();
  // `command`, then its reply read by `parse` (bytes to an optional value): the value, or the
  // command's failure, or "the <what> reply on <link> <wrong>" when parse finds nothing.
  template <class T, class Parse>
  boost::asio::awaitable<Step<T>> query(Command command, Parse parse, std::string what, std::string wrong);

  SessionIo& io_;
  std::chrono::milliseconds reply_timeout_{1000};
  int attempts_ = 2;
  std::optional<Command> health_command_;
};

}  // namespace ydscope
