// The supervisor coroutine of a Session: open the link, start the device up as the manuals say,
// hand over to serve() (session_intents.cpp) while laps flow, and on a fault reconnect with
// backoff. I/O thread only.
#include <algorithm>
#include <cstdio>
#include <exception>
#include <utility>  // before asio's coroutine headers, which use std::exchange without including it
#include <vector>

#include <boost/asio/co_spawn.hpp>
#include <boost/asio/redirect_error.hpp>
#include <boost/asio/use_awaitable.hpp>

#include "core/link/device_probe.h"
#include "core/link/link_address.h"
#include "core/link/recorded_device.h"
#include "core/link/session_impl.h"

namespace ydscope {

namespace asio = boost::asio;
using namespace std::chrono_literals;

namespace {
// A serial port's return is seen by the PortWatch at once, so its timer is only the fallback and
// for faults that are not a missing port. A TCP bridge cannot be watched: its backoff stays short
// enough that a restarted bridge is used again within a second (a refused connect costs nothing).
constexpr std::chrono::milliseconds kMaxTcpBackoff{750};

// The serial device path a session opens, when it opens one (not TCP, not a test's own opener).
std::optional<std::string> watchable_path(const SessionConfig& config) {
  if (config.open_link) return std::nullopt;
  std::string ignored;
  const auto address = parse_link_address(config.address, ignored);
  if (!address || address->kind != LinkAddress::Kind::Serial) return std::nullopt;
  return address->path;
}

std::string seconds_text(std::chrono::milliseconds duration) {
  char text[16];
  std::snprintf(text, sizeof text, "%.2g s", static_cast<double>(duration.count()) / 1000.0);
  return text;
}

std::string baud_list(const std::vector<std::uint32_t>& bauds) {
  std::string text;
  for (std::size_t i = 0; i < bauds.size(); ++i) text += (i ? ", " : "") + std::to_string(bauds[i]);
  return text;
}

std::vector<std::uint32_t> candidate_bauds(const SessionConfig& config) {
  std::vector<std::uint32_t> bauds;
  const auto add = [&](std::uint32_t baud) {
    if (std::find(bauds.begin(), bauds.end(), baud) == bauds.end()) bauds.push_back(baud);
  };
  if (config.baud) add(*config.baud);
  if (config.probe_baud) {
    for (const auto baud : kProbeBauds) add(baud);
  } else if (!config.baud) {
    if (config.model) {
      add(profile_for(*config.model).default_baud);
    } else {  // unknown model: the default bauds of every model
      for (const auto& profile : all_profiles()) add(profile.default_baud);
    }
  }
  return bauds;
}

}  // namespace

void Session::Impl::spawn_supervisor() {
  SessionConfig config = std::move(*pending_config_);
  pending_config_.reset();
  config_ = config;
  supervisor_running_ = true;
  disconnect_requested_ = false;
  // What the snapshot says about a device belongs to the connection that learned it: a replay
  // after a G1 session must not show the G1's health answer or set rate.
  counters_.reset();
  publish([](SessionSnapshot& s) {
    const SessionSnapshot fresh;
    s.link = fresh.link;
    s.baud = fresh.baud;
    s.device = fresh.device;
    s.health = fresh.health;
    s.scan_hz = fresh.scan_hz;
    s.ranging_khz = fresh.ranging_khz;
    s.power_down_protection = fresh.power_down_protection;
    s.distance_scale = fresh.distance_scale;
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
      set_state(LinkState::Failed, why);
    }
    fail_pending_intents("the session ended");
    if (pending_config_ && !stopping_) spawn_supervisor();
  });
}

asio::awaitable<void> Session::Impl::supervise(SessionConfig config) {
  sequencer_.configure(config.reply_timeout, config.command_attempts);
  auto delay = config.first_backoff;
  while (!disconnect_requested_ && !stopping_) {
    std::string error;
    if (co_await connect_and_start(config, error)) {
      delay = config.first_backoff;
      co_await serve();
      if (disconnect_requested_ || stopping_) break;
      error = link_.fault().empty() ? "the link closed" : link_.fault();
    }
    link_.detach();
    fail_pending_intents(error);
    if (disconnect_requested_ || stopping_) break;
    if (!config.reconnect) {
      set_state(LinkState::Failed, error);
      co_return;
    }
    const auto port_path = watchable_path(config);
    const bool watching = port_path && port_watch_.arm(*port_path, [this] {
      port_changed_ = true;
      notify();
    });
    set_state(LinkState::Reconnecting,
              error + (watching ? "; retrying when " + *port_path + " comes back, or in " : "; retrying in ") +
                  seconds_text(delay));
    co_await backoff(delay);
    port_watch_.disarm();
    counters_.add_reconnect();
    const bool tcp = !port_path && !config.open_link;
    delay = std::min(delay * 2, tcp ? std::min(config.max_backoff, kMaxTcpBackoff) : config.max_backoff);
  }
  if (link_.attached() && !stopping_) {
    if (link_.device_scanning()) {  // leave the lidar stopped, as we found it
      link_.stop_stream();
      link_.send(Command::Stop);
      co_await link_.sleep(30ms);
    }
  }
  link_.detach();
  if (!stopping_) set_state(LinkState::Idle, "disconnected");
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

asio::awaitable<bool> Session::Impl::connect_and_start(const SessionConfig& config, std::string& error) {
  set_state(LinkState::Connecting, "opening " + config.address);
  const std::vector<std::uint32_t> bauds = candidate_bauds(config);
  std::unique_ptr<ByteLink> opened;
  if (config.open_link)
    opened = config.open_link(io_, bauds.front(), error);
  else
    opened = co_await open_byte_link(io_, config.address, bauds.front(), error);
  if (!opened) {
    if (error.empty()) error = "cannot open " + config.address;
    co_return false;
  }
  const bool commands = opened->accepts_commands();
  link_.attach(std::move(opened));
  const auto publish_link = [this](std::uint32_t baud) {
    const std::string text = link_.link() ? link_.link()->describe() : std::string();
    publish([&](SessionSnapshot& s) {
      s.link = text;
      s.baud = baud;
    });
  };
  publish_link(bauds.front());

  if (!commands) {  // a replay: nothing to ask, decode what comes
    profile_ = &profile_for(config.model.value_or(Model::G6));
    new_decoder();
    DeviceDetails device;
    device.profile = profile_;
    if (const RecordingMetadata* recorded = link_.link()->recording_metadata())
      device = recorded_device(*recorded, *profile_);
    publish([&device](SessionSnapshot& s) { s.device = device; });
    link_.listen_stream();
    scan_.scanning_from(link_clock_ns());
    set_state(LinkState::Scanning, "");
    co_return true;
  }

  set_state(LinkState::Probing, "asking " + link_.link()->describe() + " for its device info");
  sequencer_.reset_device();
  Step<DeviceInfo> info;
  std::uint32_t baud = bauds.front();
  for (std::size_t i = 0; i < bauds.size(); ++i) {
    if (disconnect_requested_ || stopping_) co_return false;
    if (i > 0) {
      if (!link_.link()->set_baud(bauds[i], error)) co_return false;
      publish_link(bauds[i]);
    }
    co_await sequencer_.pause_scan(true);  // a device left scanning answers nothing else
    info = co_await sequencer_.device_info();
    if (info.ok()) {
      baud = bauds[i];
      break;
    }
    if (info.link_lost) break;
  }
  if (!info.ok()) {
    if (bauds.size() > 1 && !info.link_lost)
      error = "no device-info reply (A5 90) at any of " + baud_list(bauds) + " baud on " + config.address +
              ": is it a G1, G6 or TG lidar, powered, on this port?";
    else
      error = info.error;
    co_return false;
  }
  std::string note;
  profile_ = choose_profile(config.model, info.value->model_code, note);
  if (!profile_) {
    error = note;
    co_return false;
  }
  new_decoder();
  const DeviceDetails details = make_device_details(*info.value, *profile_);
  publish([&](SessionSnapshot& s) {
    s.device = details;
    s.baud = baud;
  });

  // The rest of start-up is informative: a model without an answer still scans.
  const auto health = co_await sequencer_.health(*profile_);
  if (health.link_lost) co_return false;
  const auto scan_hz = co_await sequencer_.scan_hz();
  if (scan_hz.link_lost) co_return false;
  const auto ranging = co_await sequencer_.ranging_khz(*profile_);
  if (ranging.link_lost) co_return false;
  std::optional<bool> protection;
  if (power_down_wanted_) {  // a replugged device is back to its default (off)
    const auto step = co_await sequencer_.power_down_protection(true);
    if (step.link_lost) co_return false;
    protection = step.value;
  }
  link_.allow_scan_keepalive(protection.value_or(false));
  publish([&](SessionSnapshot& s) {
    s.health = health.value;
    s.scan_hz = scan_hz.value;
    s.ranging_khz = ranging.value;
    s.power_down_protection = protection;
  });
  record_metadata();
  if (!health.ok() && note.empty()) note = "health: " + health.error;

  if (!config.scan) {
    set_state(LinkState::Ready, note);
    co_return true;
  }
  scan_.scanning_from(link_clock_ns());
  if (!link_.start_stream()) {
    error = "could not send A5 60 to " + config.address;
    co_return false;
  }
  set_state(LinkState::Scanning, note);
  co_return true;
}

void Session::Impl::record_metadata() {
  if (!recording_.capturing()) return;
  recording_.record_metadata(recording_metadata_of(snapshot(), config_ ? std::optional(config_->address) : std::nullopt,
                                                   scan_.distance_scale()));
}

}  // namespace ydscope
