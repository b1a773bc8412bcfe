#pragma once
// Session::Impl: the I/O thread's side of a Session. session.cpp holds the thread, the intents
// and the snapshot; session_supervisor.cpp the connect / start-up / reconnect coroutine;
// session_intents.cpp the intents served while scanning.
#include <chrono>
#include <condition_variable>
#include <cstdint>
#include <deque>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <thread>

#include <boost/asio/executor_work_guard.hpp>
#include <boost/asio/io_context.hpp>
#include <boost/asio/steady_timer.hpp>

#include "core/link/command_sequencer.h"
#include "core/link/port_watch.h"
#include "core/link/session.h"
#include "core/link/session_io.h"
#include "core/link/recording_control.h"
#include "core/link/running_scan.h"
#include "core/protocol/scan_decoder.h"

namespace ydscope {

class Session::Impl {
 public:
  Impl(LapStream& stream, const LapSubscription& main_consumer);
  ~Impl();

  // ---- any thread -------------------------------------------------------------------------
  void post_connect(SessionConfig config);
  void post_disconnect();
  struct Intent {
    enum class Kind { ScanHz, RangingKhz, PowerDown, Health } kind;
    double hz = 0;
    std::uint16_t khz = 0;
    bool on = false;
    CommandCallback done;
  };
  void post_intent(Intent intent);
  void post_start_recording(std::string path, CommandCallback done);
  void post_stop_recording(CommandCallback done);
  void post_start_tap(std::shared_ptr<RecordTap> tap, CommandCallback done);
  void post_stop_tap(std::shared_ptr<RecordTap> tap, CommandCallback done);
  void post_distance_scale(std::optional<double> scale);
  SessionSnapshot snapshot() const;
  SessionSnapshot wait_until(const std::function<bool(const SessionSnapshot&)>& done,
                             std::chrono::milliseconds timeout) const;

  // ---- I/O thread ---------------------------------------------------------------------------
 private:
  void run_thread();
  void shutdown();
  void notify() { signal_.cancel(); }
  void start_tick();
  void on_tick();
  // A fresh decoder for profile_ (RunningScan::restart), its scale published.
  void new_decoder();
  void set_state(LinkState state, std::string message);
  void publish(const std::function<void(SessionSnapshot&)>& change);
  void finish(const CommandResult& result, const CommandCallback& done);
  void fail_pending_intents(const std::string& why);

  void spawn_supervisor();
  boost::asio::awaitable<void> supervise(SessionConfig config);
  boost::asio::awaitable<bool> connect_and_start(const SessionConfig& config, std::string& error);
  boost::asio::awaitable<void> serve();
  boost::asio::awaitable<void> run_intent(Intent intent);
  boost::asio::awaitable<void> backoff(std::chrono::milliseconds duration);
  // A metadata record of what the session knows now, to whatever captures.
  void record_metadata();
  void publish_recording();  // the file's state, for the snapshot
  RecordingMetadata capture_start_metadata() const;

  LapStream& stream_;
  const LapSubscription& main_consumer_;  // Session::laps(), whose counts the snapshot names
  boost::asio::io_context io_;
  boost::asio::executor_work_guard<boost::asio::io_context::executor_type> work_;
  SessionCounters counters_;
  SessionIo link_;
  CommandSequencer sequencer_;
  boost::asio::steady_timer signal_;  // the supervisor's wait; notify() ends it early
  boost::asio::steady_timer tick_;    // watchdog, rates, power-down keepalive
  PortWatch port_watch_;              // ends a reconnect's backoff when the serial port comes back
  bool port_changed_ = false;

  // I/O thread only.
  bool stopping_ = false;
  bool supervisor_running_ = false;
  bool disconnect_requested_ = false;
  std::optional<SessionConfig> pending_config_;
  std::optional<SessionConfig> config_;
  std::deque<Intent> intents_;
  const ModelProfile* profile_ = nullptr;
  RunningScan scan_{stream_, counters_};  // decoding, publishing, stall and keep-alive watch
  bool power_down_wanted_ = false;
  std::int64_t last_rate_tick_ns_ = 0;
  LinkState state_ = LinkState::Idle;
  RecordingControl recording_{link_};

  // Shared with readers.
  mutable std::mutex mutex_;
  mutable std::condition_variable changed_;
  SessionSnapshot shared_;

  std::thread thread_;  // last: starts after everything above exists
};

}  // namespace ydscope
