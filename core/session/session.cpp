#include "core/session/session.h"

#include <pthread.h>

#include <cmath>
#include <cstdio>
#include <exception>

#include <boost/asio/post.hpp>

#include "core/session/device_probe.h"
#include "core/session/session_impl.h"
#include "core/version.h"

namespace ydscope {

namespace asio = boost::asio;
using namespace std::chrono_literals;

namespace {
constexpr auto kTickPeriod = 250ms;
constexpr std::int64_t kRatePeriodNs = 1'000'000'000;
}  // namespace

// ---- Session: thin forwarding ---------------------------------------------------------------

Session::Session(std::size_t queue_capacity, WakeFn wake, std::string consumer)
    : laps_(stream_.subscribe(std::move(consumer), queue_capacity, std::move(wake))),
      impl_(std::make_unique<Impl>(stream_, *laps_)) {}

Session::~Session() = default;

void Session::connect(SessionConfig config) { impl_->post_connect(std::move(config)); }
void Session::disconnect() { impl_->post_disconnect(); }
void Session::set_scan_hz(double target_hz, CommandCallback done) {
  impl_->post_intent({SessionIntent::Kind::ScanHz, target_hz, 0, false, std::move(done)});
}
void Session::set_ranging_khz(std::uint16_t target_khz, CommandCallback done) {
  impl_->post_intent({SessionIntent::Kind::RangingKhz, 0, target_khz, false, std::move(done)});
}
void Session::set_power_down_protection(bool on, CommandCallback done) {
  impl_->post_intent({SessionIntent::Kind::PowerDown, 0, 0, on, std::move(done)});
}
void Session::refresh_health(CommandCallback done) {
  impl_->post_intent({SessionIntent::Kind::Health, 0, 0, false, std::move(done)});
}
void Session::start_recording(std::string path, CommandCallback done) {
  impl_->post_start_recording(std::move(path), std::move(done));
}
void Session::stop_recording(CommandCallback done) { impl_->post_stop_recording(std::move(done)); }
void Session::start_tap(std::shared_ptr<RecordTap> tap, CommandCallback done) {
  impl_->post_start_tap(std::move(tap), std::move(done));
}
void Session::stop_tap(std::shared_ptr<RecordTap> tap, CommandCallback done) {
  impl_->post_stop_taps({std::move(tap)}, std::move(done));
}
void Session::stop_taps(std::vector<std::shared_ptr<RecordTap>> taps, CommandCallback done) {
  impl_->post_stop_taps(std::move(taps), std::move(done));
}
void Session::set_distance_scale(std::optional<double> mm_per_count) { impl_->post_distance_scale(mm_per_count); }
void Session::set_reading(Reading reading) { impl_->post_reading(reading); }
SessionSnapshot Session::snapshot() const { return impl_->snapshot(); }
SessionSnapshot Session::wait_until(const std::function<bool(const SessionSnapshot&)>& done,
                                    std::chrono::milliseconds timeout) const {
  return impl_->wait_until(done, timeout);
}

std::string describe_snapshot(const SessionSnapshot& s) {
  std::string text(link_state_name(s.state));
  if (s.device && s.device->profile) text += ": " + std::string(s.device->profile->name);
  if (!s.link.empty()) text += " on " + s.link;
  if (!s.message.empty()) text += " (" + s.message + ")";
  return text;
}

// ---- Impl: thread and lifetime --------------------------------------------------------------

Session::Impl::Impl(LapStream& stream, const LapSubscription& main_consumer)
    : stream_(stream),
      main_consumer_(main_consumer),
      work_(io_.get_executor()),
      link_(io_, counters_),
      sequencer_(link_),
      signal_(io_),
      tick_(io_),
      port_watch_(io_) {
  link_.on_fault([this] { notify(); });
  link_.on_stream([this](std::span<const std::uint8_t> bytes, std::int64_t rx_ns) { return scan_.feed(bytes, rx_ns); });
  thread_ = std::thread([this] { run_thread(); });
}

Session::Impl::~Impl() {
  asio::post(io_, [this] { shutdown(); });
  work_.reset();
  if (thread_.joinable()) thread_.join();
}

void Session::Impl::run_thread() {
  pthread_setname_np(pthread_self(), "ydscope-io");  // so top, perf and debuggers can tell it apart
  start_tick();
  // The last boundary: nothing thrown on this thread may end the program or leave it.
  for (;;) {
    try {
      io_.run();
      return;
    } catch (const std::exception& e) {
      board_.set_state(LinkState::Failed, std::string("internal error on the I/O thread: ") + e.what());
    } catch (...) {
      board_.set_state(LinkState::Failed, "internal error on the I/O thread");
    }
  }
}

void Session::Impl::shutdown() {
  stopping_ = true;
  disconnect_requested_ = true;
  pending_config_.reset();
  recording_.stop_file();
  // A running supervisor stops a scanning lidar before it lets the link go (supervise's end).
  if (!supervisor_running_) link_.detach();
  notify();
  tick_.cancel();
}

// ---- intents (any thread -> I/O thread) -----------------------------------------------------

void Session::Impl::post_connect(SessionConfig config) {
  asio::post(io_, [this, config = std::move(config)]() mutable {
    if (stopping_) return;
    pending_config_ = std::move(config);
    if (supervisor_running_) {
      disconnect_requested_ = true;
      notify();
      return;  // the supervisor starts the pending one as it ends
    }
    spawn_supervisor();
  });
}

void Session::Impl::post_disconnect() {
  asio::post(io_, [this] {
    pending_config_.reset();
    if (supervisor_running_) {
      disconnect_requested_ = true;
      notify();
    }
  });
}

void Session::Impl::post_intent(SessionIntent intent) {
  asio::post(io_, [this, intent = std::move(intent)]() mutable {
    const LinkState state = board_.state();
    const bool down = state == LinkState::Reconnecting || state == LinkState::Stalled || state == LinkState::Failed;
    if (!supervisor_running_ || stopping_ || down) {
      CommandResult result;
      result.message = down ? "the lidar is not connected right now (" + std::string(link_state_name(state)) + ")"
                            : "not connected to a lidar: connect first";
      board_.post_result(result, intent.done);
      return;
    }
    intents_.push(std::move(intent));
    notify();
  });
}

RecordingMetadata Session::Impl::capture_start_metadata() const {
  RecordingMetadata metadata;
  metadata.start_wall_time = iso8601_utc_now();
  metadata.software = std::string("ydscope ") + kVersion;
  if (config_) metadata.port = config_->address;
  return metadata;
}

void Session::Impl::publish_recording() {
  const bool active = recording_.file_active();
  const std::string path = active ? recording_.file_path() : std::string();
  board_.publish([&](SessionSnapshot& s) {
    s.recording = active;
    s.recording_path = path;
  });
}

void Session::Impl::post_start_recording(std::string path, CommandCallback done) {
  asio::post(io_, [this, path = std::move(path), done = std::move(done)] {
    const CommandResult result = recording_.start_file(path, capture_start_metadata());
    if (result.ok) record_metadata();
    publish_recording();
    board_.post_result(result, done);
  });
}

void Session::Impl::post_stop_recording(CommandCallback done) {
  asio::post(io_, [this, done = std::move(done)] {
    const CommandResult result = recording_.stop_file();
    publish_recording();
    board_.post_result(result, done);
  });
}

void Session::Impl::post_start_tap(std::shared_ptr<RecordTap> tap, CommandCallback done) {
  asio::post(io_, [this, tap = std::move(tap), done = std::move(done)]() mutable {
    const CommandResult result = recording_.start_tap(std::move(tap), capture_start_metadata());
    record_metadata();
    board_.post_result(result, done);
  });
}

void Session::Impl::post_stop_taps(std::vector<std::shared_ptr<RecordTap>> taps, CommandCallback done) {
  asio::post(io_, [this, taps = std::move(taps), done = std::move(done)] {
    CommandResult result;
    for (const auto& tap : taps) result = recording_.stop_tap(tap);  // each is ok; the last one's words
    board_.post_result(result, done);
  });
}

void Session::Impl::post_reading(Reading reading) {
  asio::post(io_, [this, reading] {
    reading_override_ = reading;  // kept across reconnects
    if (!profile_) return;
    conventions_ = &conventions_for(*profile_, sdk_firmware_, reading);
    new_decoder();
    record_metadata();
  });
}

void Session::Impl::post_distance_scale(std::optional<double> scale) {
  asio::post(io_, [this, scale] {
    scan_.set_scale_override(scale);
    if (profile_) new_decoder();
  });
}

// ---- snapshot -------------------------------------------------------------------------------

SessionSnapshot Session::Impl::snapshot() const {
  SessionSnapshot s = board_.read();
  s.counters = counters_.read(link_clock_ns());
  s.queue_dropped = main_consumer_.dropped_full();
  s.queue_skipped = main_consumer_.skipped();
  s.consumers = stream_.stats();
  return s;
}

SessionSnapshot Session::Impl::wait_until(const std::function<bool(const SessionSnapshot&)>& done,
                                          std::chrono::milliseconds timeout) const {
  return board_.wait_until([this] { return snapshot(); }, done, timeout);
}

// ---- the byte path --------------------------------------------------------------------------

void Session::Impl::new_decoder() {
  const double scale = scan_.restart(*profile_, *conventions_);
  board_.publish([scale, conventions = conventions_](SessionSnapshot& s) {
    s.distance_scale = scale;
    s.conventions = conventions;
  });
}

// ---- the tick: rates, stall watchdog, power-down keepalive ----------------------------------

void Session::Impl::start_tick() {
  if (stopping_) return;
  tick_.expires_after(kTickPeriod);
  tick_.async_wait([this](const boost::system::error_code& ec) {
    if (ec || stopping_) return;
    on_tick();
    start_tick();
  });
}

void Session::Impl::on_tick() {
  const std::int64_t now = link_clock_ns();
  if (now - last_rate_tick_ns_ >= kRatePeriodNs) {
    counters_.tick(now);
    last_rate_tick_ns_ = now;
    if (recording_.file_active()) {
      const std::optional<std::string> stopped = recording_.flush_file();
      const bool recording = recording_.file_active();
      board_.publish([&](SessionSnapshot& s) {
        s.recording = recording;
        if (stopped) s.message = "recording stopped: " + *stopped;
      });
    }
  }
  if (board_.state() != LinkState::Scanning || !link_.device_scanning() || !config_) return;
  if (intents_.power_down_wanted() && scan_.keepalive_due(now))
    link_.send(Command::Scan);  // the keepalive the power-down mode needs; SessionIo allows only this
  if (const auto quiet_ns = scan_.stalled_for(now, config_->stall_timeout)) {
    char seconds[16];
    std::snprintf(seconds, sizeof seconds, "%.1f", static_cast<double>(*quiet_ns) * 1e-9);
    const std::string why = std::string("no data for ") + seconds + " s from " +
                            (link_.link() ? link_.link()->describe() : std::string("the port")) +
                            " while scanning: is the lidar powered and its cable seated?";
    board_.set_state(LinkState::Stalled, why);
    link_.fail(why);
  } else if (ByteLink* link = link_.link(); link && profile_) {
    // Bytes flow but no packet verifies: say why (wrong baud, another layout) rather than wait.
    const auto baud = static_cast<std::uint32_t>(std::lround(link->line_bytes_per_s() * 10));
    if (const std::optional<std::string> why = scan_.diagnosis(*profile_, baud)) {
      board_.set_state(LinkState::Stalled, *why);
      link_.fail(*why);
    }
  }
}

}  // namespace ydscope
