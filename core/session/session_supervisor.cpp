// The supervisor coroutine of a Session: start the device up (device_startup.h), serve the
// user's intents (intent_runner.h) while laps flow, and on a fault reconnect with backoff. I/O
// thread only.
#include <exception>
#include <utility>  // before asio's coroutine headers, which use std::exchange without including it

#include <boost/asio/co_spawn.hpp>
#include <boost/asio/redirect_error.hpp>
#include <boost/asio/use_awaitable.hpp>

#include "core/session/device_startup.h"
#include "core/session/reconnect_plan.h"
#include "core/session/session_impl.h"

namespace ydscope {

namespace asio = boost::asio;
using namespace std::chrono_literals;

void Session::Impl::spawn_supervisor() {
  SessionConfig config = std::move(*pending_config_);
  pending_config_.reset();
  // The user's settings were for the lidar on that port; another port is another lidar.
  if (config_ && config_->address != config.address) intents_.forget_settings();
  config_ = config;
  supervisor_running_ = true;
  disconnect_requested_ = false;
  // What the snapshot says about a device belongs to the connection that learned it: a replay
  // after a G1 session must not show the G1's health answer or set rate.
  counters_.reset();
  board_.publish([](SessionSnapshot& s) {
    const SessionSnapshot fresh;
    s.link = fresh.link;
    s.baud = fresh.baud;
    s.device = fresh.device;
    s.health = fresh.health;
    s.scan_hz = fresh.scan_hz;
    s.ranging_khz = fresh.ranging_khz;
    s.power_down_protection = fresh.power_down_protection;
    s.distance_scale = fresh.distance_scale;
    s.conventions = fresh.conventions;
    s.last_result = fresh.last_result;
  });
  asio::co_spawn(io_, supervise(std::move(config)), [this](std::exception_ptr error) {
    supervisor_running_ = false;
    link_.detach();
    if (error) {
      std::string why = "internal error in the session";
      try {
        std::rethrow_exception(error);
      } catch (const std::exception& e) {
        why += std::string(": ") + e.what();
      } catch (...) {
      }
      board_.set_state(LinkState::Failed, why);
    }
    intents_.fail_all("the session ended");
    if (pending_config_ && !stopping_) spawn_supervisor();
  });
}

asio::awaitable<void> Session::Impl::supervise(SessionConfig config) {
  sequencer_.configure(config.reply_timeout, config.command_attempts);
  ReconnectPlan plan(config);
  bool again = false;  // it started before: this start is a reconnect
  while (!disconnect_requested_ && !stopping_) {
    std::string error;
    if (co_await connect_and_start(config, again, error)) {
      again = true;
      plan.started();
      co_await serve();
      if (disconnect_requested_ || stopping_) break;
      error = link_.fault().empty() ? "the link closed" : link_.fault();
    }
    link_.detach();
    intents_.fail_all(error);
    if (disconnect_requested_ || stopping_) break;
    if (!config.reconnect || plan.hopeless()) {  // said once; retrying could not help
      outage_.down("gave up on " + config.address + ": " + error);
      board_.set_state(LinkState::Failed, error);
      co_return;
    }
    outage_.down("reconnecting to " + config.address + ": " + error);
    const auto& port_path = plan.watched_path();
    const bool watching = port_path && port_watch_.arm(*port_path, [this] {
      port_changed_ = true;
      notify();
    });
    board_.set_state(LinkState::Reconnecting, error + plan.retry_text(watching));
    co_await backoff(plan.delay());
    port_watch_.disarm();
    counters_.add_reconnect();
    plan.waited();
  }
  // Leave the lidar stopped, as we found it, however the session ends: a disconnect, or the
  // program ending (SIGTERM, --seconds, a closed window, an error unwinding): a real unit left
  // scanning keeps its motor and laser on.
  if (link_.attached() && link_.device_scanning()) {
    link_.stop_stream();
    link_.send(Command::Stop);
    co_await link_.sleep(30ms);
  }
  link_.detach();
  if (!stopping_) board_.set_state(LinkState::Idle, "disconnected");
}

asio::awaitable<void> Session::Impl::backoff(std::chrono::milliseconds duration) {
  const auto deadline = std::chrono::steady_clock::now() + duration;
  port_changed_ = false;
  while (!disconnect_requested_ && !stopping_ && !port_changed_ && std::chrono::steady_clock::now() < deadline) {
    signal_.expires_at(deadline);
    boost::system::error_code ec;
    co_await signal_.async_wait(asio::redirect_error(asio::use_awaitable, ec));
  }
}

// While connected: the user's intents, one at a time, until a fault or a disconnect.
asio::awaitable<void> Session::Impl::serve() {
  while (!disconnect_requested_ && !stopping_ && link_.attached() && link_.fault().empty()) {
    if (intents_.pending()) {
      co_await intents_.run_next(profile_);
      continue;
    }
    signal_.expires_at(asio::steady_timer::time_point::max());
    boost::system::error_code ec;
    co_await signal_.async_wait(asio::redirect_error(asio::use_awaitable, ec));
  }
}

asio::awaitable<bool> Session::Impl::connect_and_start(const SessionConfig& config, bool again, std::string& error) {
  const StartupParts parts{io_, link_, sequencer_, board_, [this] { return disconnect_requested_ || stopping_; }};
  const StartupOutcome outcome = co_await start_device(parts, config, intents_.settings());
  if (!outcome.ok) {
    error = outcome.error;
    co_return false;
  }
  profile_ = outcome.profile;
  sdk_firmware_ = outcome.sdk_firmware;
  conventions_ =
      reading_override_ ? &conventions_for(*profile_, sdk_firmware_, *reading_override_) : outcome.conventions;
  new_decoder();
  outage_.up();
  if (!outcome.accepts_commands) {  // a replay: decode what comes
    link_.listen_stream();
    scan_.scanning_from(link_clock_ns());
    board_.set_state(LinkState::Scanning, "");
    co_return true;
  }
  link_.allow_scan_keepalive(outcome.power_down_protection.value_or(false));
  record_metadata();
  // Said where the app, serve's clients and record show the link: a reconnect, and whether the
  // user's settings are in force again.
  std::string said = again ? "reconnected" : "";
  for (const std::string* part : {&outcome.settings_note, &outcome.note})
    if (!part->empty()) said += (said.empty() ? "" : "; ") + *part;
  if (!config.scan) {
    board_.set_state(LinkState::Ready, said);
    co_return true;
  }
  scan_.scanning_from(link_clock_ns());
  if (!link_.start_stream()) {
    error = "could not send A5 60 to " + config.address;
    co_return false;
  }
  board_.set_state(LinkState::Scanning, said);
  co_return true;
}

void Session::Impl::record_metadata() {
  if (!recording_.capturing()) return;
  RecordingMetadata metadata = recording_metadata_of(
      snapshot(), config_ ? std::optional(config_->address) : std::nullopt, scan_.distance_scale());
  outage_.add_to(metadata);
  recording_.record_metadata(metadata);
}

}  // namespace ydscope
