// The Session's intents while it scans: one at a time, each as stop, command, read back, resume
// (the CommandSequencer's steps), its outcome published and handed to the caller. I/O thread only.
#include <utility>  // before asio's coroutine headers, which use std::exchange without including it

#include <boost/asio/redirect_error.hpp>
#include <boost/asio/use_awaitable.hpp>

#include "core/link/device_probe.h"
#include "core/link/session_impl.h"

namespace ydscope {

namespace asio = boost::asio;

namespace {

std::string intent_text(const Session::Impl::Intent& intent) {
  switch (intent.kind) {
    case Session::Impl::Intent::Kind::ScanHz: return "set scan frequency to " + hz_text(intent.hz);
    case Session::Impl::Intent::Kind::RangingKhz:
      return "set ranging frequency to " + std::to_string(intent.khz) + " kHz";
    case Session::Impl::Intent::Kind::PowerDown:
      return std::string("turn power-down protection ") + (intent.on ? "on" : "off");
    case Session::Impl::Intent::Kind::Health: return "read health";
  }
  return "command";
}

}  // namespace

asio::awaitable<void> Session::Impl::serve() {
  while (!disconnect_requested_ && !stopping_ && link_.attached() && link_.fault().empty()) {
    if (!intents_.empty()) {
      Intent intent = std::move(intents_.front());
      intents_.pop_front();
      co_await run_intent(std::move(intent));
      continue;
    }
    signal_.expires_at(asio::steady_timer::time_point::max());
    boost::system::error_code ec;
    co_await signal_.async_wait(asio::redirect_error(asio::use_awaitable, ec));
  }
}

asio::awaitable<void> Session::Impl::run_intent(Intent intent) {
  CommandResult result;
  result.what = intent_text(intent);
  publish([&](SessionSnapshot& s) {
    s.busy = true;
    s.busy_what = result.what;
  });
  if (!profile_ || !link_.attached()) {
    result.message = "not connected to a lidar: connect first";
    finish(result, intent.done);
    co_return;
  }
  const bool scanning = state_ == LinkState::Scanning;
  if (scanning) set_state(LinkState::CommandInProgress, result.what);
  const bool was_scanning = co_await sequencer_.pause_scan();
  bool lost = false;
  const auto settle = [&](const auto& step, const std::string& success) {
    result.ok = step.ok();
    result.message = step.ok() ? success : step.error;
    lost = step.link_lost;
  };
  switch (intent.kind) {
    case Intent::Kind::ScanHz: {
      const auto step = co_await sequencer_.step_scan_hz(*profile_, intent.hz);
      result.scan_hz = step.value;
      settle(step, step.value ? "scan frequency reads back " + hz_text(*step.value) : "");
      if (step.value) publish([&](SessionSnapshot& s) { s.scan_hz = step.value; });
      break;
    }
    case Intent::Kind::RangingKhz: {
      const auto step = co_await sequencer_.cycle_ranging_to(*profile_, intent.khz);
      result.ranging_khz = step.value;
      settle(step, step.value ? "ranging frequency reads back " + std::to_string(*step.value) + " kHz" : "");
      if (step.value) publish([&](SessionSnapshot& s) { s.ranging_khz = step.value; });
      break;
    }
    case Intent::Kind::PowerDown: {
      const auto step = co_await sequencer_.power_down_protection(intent.on);
      result.power_down_protection = step.value;
      settle(step, std::string("power-down protection is ") + (intent.on ? "on" : "off"));
      if (step.value) {
        power_down_wanted_ = *step.value;
        link_.allow_scan_keepalive(*step.value);
        publish([&](SessionSnapshot& s) { s.power_down_protection = step.value; });
      }
      break;
    }
    case Intent::Kind::Health: {
      const auto step = co_await sequencer_.health(*profile_);
      result.health = step.value;
      settle(step, step.value ? "health: " + step.value->summary : "");
      if (step.value) publish([&](SessionSnapshot& s) { s.health = step.value; });
      break;
    }
  }
  if (lost || !link_.attached()) {
    result.ok = false;
    finish(result, intent.done);
    co_return;  // serve() sees the fault; the supervisor reconnects
  }
  if (was_scanning) {
    new_decoder();  // the lap cut by the stop is not a lap
    scan_.scanning_from(link_clock_ns());
    if (!sequencer_.resume_scan(true)) {
      result.ok = false;
      result.message += "; and A5 60 could not be sent to resume the scan";
    }
  }
  if (scanning) set_state(LinkState::Scanning, "");
  if (result.ok) record_metadata();
  finish(result, intent.done);
}

void Session::Impl::fail_pending_intents(const std::string& why) {
  while (!intents_.empty()) {
    Intent intent = std::move(intents_.front());
    intents_.pop_front();
    CommandResult result;
    result.what = intent_text(intent);
    result.message = "not done: " + why;
    finish(result, intent.done);
  }
}

}  // namespace ydscope
