#include "core/session/intent_runner.h"

#include "core/session/device_probe.h"

namespace ydscope {

namespace asio = boost::asio;

std::string intent_text(const SessionIntent& intent) {
  switch (intent.kind) {
    case SessionIntent::Kind::ScanHz: return "set scan frequency to " + hz_text(intent.hz);
    case SessionIntent::Kind::RangingKhz: return "set ranging frequency to " + std::to_string(intent.khz) + " kHz";
    case SessionIntent::Kind::PowerDown: return std::string("turn power-down protection ") + (intent.on ? "on" : "off");
    case SessionIntent::Kind::Health: return "read health";
  }
  return "command";
}

asio::awaitable<void> IntentRunner::run_next(const ModelProfile* profile) {
  SessionIntent intent = std::move(queue_.front());
  queue_.pop_front();
  CommandResult result;
  result.what = intent_text(intent);
  parts_.board.publish([&](SessionSnapshot& s) {
    s.busy = true;
    s.busy_what = result.what;
  });
  if (!profile || !parts_.link.attached()) {
    result.message = "not connected to a lidar: connect first";
    parts_.board.post_result(result, intent.done);
    co_return;
  }
  const bool scanning = parts_.board.state() == LinkState::Scanning;
  if (scanning) parts_.board.set_state(LinkState::CommandInProgress, result.what);
  const bool was_scanning = co_await parts_.sequencer.pause_scan();
  bool lost = false;
  co_await run(intent, *profile, result, lost);
  if (lost || !parts_.link.attached()) {
    result.ok = false;
    parts_.board.post_result(result, intent.done);
    co_return;  // the session's serve loop sees the fault; its supervisor reconnects
  }
  if (was_scanning) {
    parts_.restart_decoder();
    parts_.scan.scanning_from(link_clock_ns());
    if (!parts_.sequencer.resume_scan(true)) {
      result.ok = false;
      result.message += "; and A5 60 could not be sent to resume the scan";
    }
  }
  if (scanning) parts_.board.set_state(LinkState::Scanning, "");
  if (result.ok) parts_.record_metadata();
  parts_.board.post_result(result, intent.done);
}

// The command and its read-back, with the scan already stopped.
asio::awaitable<void> IntentRunner::run(const SessionIntent& intent, const ModelProfile& profile, CommandResult& result,
                                        bool& lost) {
  const auto settle = [&](const auto& step, const std::string& success) {
    result.ok = step.ok();
    result.message = step.ok() ? success : step.error;
    lost = step.link_lost;
  };
  SnapshotBoard& board = parts_.board;
  switch (intent.kind) {
    case SessionIntent::Kind::ScanHz: {
      const auto step = co_await parts_.sequencer.step_scan_hz(profile, intent.hz);
      result.scan_hz = step.value;
      settle(step, step.value ? "scan frequency reads back " + hz_text(*step.value) : "");
      if (step.value) board.publish([&](SessionSnapshot& s) { s.scan_hz = step.value; });
      if (step.ok()) settings_.scan_hz = step.value;
      break;
    }
    case SessionIntent::Kind::RangingKhz: {
      const auto step = co_await parts_.sequencer.cycle_ranging_to(profile, intent.khz);
      result.ranging_khz = step.value;
      settle(step, step.value ? "ranging frequency reads back " + std::to_string(*step.value) + " kHz" : "");
      if (step.value) board.publish([&](SessionSnapshot& s) { s.ranging_khz = step.value; });
      if (step.ok()) settings_.ranging_khz = step.value;
      break;
    }
    case SessionIntent::Kind::PowerDown: {
      const auto step = co_await parts_.sequencer.power_down_protection(intent.on);
      result.power_down_protection = step.value;
      settle(step, std::string("power-down protection is ") + (intent.on ? "on" : "off"));
      if (step.value) {
        settings_.power_down_protection = step.value;
        parts_.link.allow_scan_keepalive(*step.value);
        board.publish([&](SessionSnapshot& s) { s.power_down_protection = step.value; });
      }
      break;
    }
    case SessionIntent::Kind::Health: {
      const auto step = co_await parts_.sequencer.health(profile);
      result.health = step.value;
      settle(step, step.value ? "health: " + step.value->summary : "");
      if (step.value) board.publish([&](SessionSnapshot& s) { s.health = step.value; });
      break;
    }
  }
}

void IntentRunner::fail_all(const std::string& why) {
  while (!queue_.empty()) {
    SessionIntent intent = std::move(queue_.front());
    queue_.pop_front();
    CommandResult result;
    result.what = intent_text(intent);
    result.message = "not done: " + why;
    parts_.board.post_result(result, intent.done);
  }
}

}  // namespace ydscope
