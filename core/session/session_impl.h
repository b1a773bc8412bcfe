#pragma once
// Session::Impl: the I/O thread's side of a Session, and the parts it is made of. session.cpp holds
// the thread, what callers post and the snapshot; session_supervisor.cpp the connect / reconnect
// coroutine. Start-up is device_startup.h, the user's intents intent_runner.h, the running
// stream running_scan.h, commands command_sequencer.h, files and taps recording_control.h.
#include <chrono>
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <thread>

#include <boost/asio/executor_work_guard.hpp>
#include <boost/asio/io_context.hpp>
#include <boost/asio/steady_timer.hpp>

#include "core/session/command_sequencer.h"
#include "core/session/intent_runner.h"
#include "core/session/link_outage.h"
#include "core/link/port_watch.h"
#include "core/session/session.h"
#include "core/session/session_io.h"
#include "core/session/snapshot_board.h"
#include "core/session/recording_control.h"
#include "core/session/running_scan.h"
#include "core/protocol/scan_decoder.h"

namespace ydscope {

class Session::Impl {
 public:
  Impl(LapStream& stream, const LapSubscription& main_consumer);
  ~Impl();

  // ---- any thread -------------------------------------------------------------------------
  void post_connect(SessionConfig config);
  void post_disconnect();
  void post_intent(SessionIntent intent);
  void post_start_recording(std::string path, CommandCallback done);
  void post_stop_recording(CommandCallback done);
  void post_start_tap(std::shared_ptr<RecordTap> tap, CommandCallback done);
  void post_stop_taps(std::vector<std::shared_ptr<RecordTap>> taps, CommandCallback done);
  void post_distance_scale(std::optional<double> scale);
  void post_reading(Reading reading);
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

  void spawn_supervisor();
  boost::asio::awaitable<void> supervise(SessionConfig config);
  // `again`: a reconnect after a fault, which the state's sentence says.
  boost::asio::awaitable<bool> connect_and_start(const SessionConfig& config, bool again, std::string& error);
  boost::asio::awaitable<void> serve();
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
  SnapshotBoard board_;  // what other threads read
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
  const ModelProfile* profile_ = nullptr;
  const UnitConventions* conventions_ = nullptr;  // with profile_: how the bytes are read
  std::optional<FirmwareVersion> sdk_firmware_;   // the unit's, in the SDK's byte order
  std::optional<Reading> reading_override_;       // set_reading's, over the config's
  RunningScan scan_{stream_, counters_};          // decoding, publishing, stall and keep-alive watch
  IntentRunner intents_{{link_, sequencer_, board_, scan_, [this] { new_decoder(); }, [this] { record_metadata(); }}};
  std::int64_t last_rate_tick_ns_ = 0;
  RecordingControl recording_{link_};
  LinkOutage outage_{recording_};  // marks the link's faults in what captures

  std::thread thread_;  // last: starts after everything above exists
};

}  // namespace ydscope
