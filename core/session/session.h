#pragma once
// Session: everything between a lidar port and its lap stream, on ONE I/O thread it owns.
//
// The I/O thread runs a boost::asio::io_context: it reads into a fixed buffer, feeds the
// ScanDecoder, publishes each complete lap once to the LapStream (every consumer has a ring of its
// own and is woken after each lap it gets), keeps counters,
// records every byte in both directions when asked, and runs commands as the manuals require
// (stop, drain, command, reply with a timeout and a bounded retry, resume the scan). Faults
// (unplugged port, stalled stream, wrong baud, silent device) become a LinkState and a sentence;
// the session reconnects by itself with backoff. No exception leaves the I/O thread.
//
// Thread contract: every public method may be called from any thread (intents are posted to the
// io_context). Completion callbacks and wake callbacks run on the I/O thread: keep them short.
// Each subscription has exactly one consumer thread: laps() is the creator's (UI or CLI); a file
// writer, a bridge or a report subscribes to lap_stream() for its own.
#include <chrono>
#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <boost/asio/io_context.hpp>

#include "core/link/byte_link.h"
#include "core/snapshot/session_snapshot.h"
#include "core/protocol/lap.h"
#include "core/protocol/model_profile.h"
#include "core/stream/lap_stream.h"

namespace ydscope {

class RecordTap;

// Opens the byte link for one attempt at `baud`; null plus one sentence in `error` on failure.
using LinkOpener =
    std::function<std::unique_ptr<ByteLink>(boost::asio::io_context& io, std::uint32_t baud, std::string& error)>;

// Bauds tried, in this order, when baud probing is on.
inline constexpr std::uint32_t kProbeBauds[] = {230400, 512000, 128000, 115200};

struct SessionConfig {
  std::string address;                           // "/dev/ttyUSB0", a pty path, or "tcp://host:port"
  std::optional<Model> model;                    // empty: detect from the device-info model code
  std::optional<std::uint32_t> baud;             // empty: the model's default (230400 when the model is unknown)
  bool probe_baud = false;                       // try kProbeBauds (starting with `baud` if given) until A5 90 answers
  bool scan = true;                              // start scanning after start-up; false for info / set
  bool reconnect = true;                         // after a fault, reopen with backoff; a serial port that comes
                                                 // back (see PortWatch) ends the wait at once
  std::chrono::milliseconds first_backoff{250};  // doubling after each failed reopen ...
  std::chrono::milliseconds max_backoff{4000};   // ... up to this (a TCP bridge: at most 750 ms)
  std::optional<double> distance_scale;          // overrides the conventions' mm per count
  // How the unit's bytes are read (unit_conventions.h). Empty: as real units of its model and
  // firmware write them, or for a replay, as the recording was read when it was made.
  std::optional<Reading> reading;
  std::chrono::milliseconds reply_timeout{1000};
  int command_attempts = 2;                       // sends per command before it is reported failed
  std::chrono::milliseconds stall_timeout{2000};  // no byte for this long while scanning = stalled
  LinkOpener open_link;                           // empty: open `address` as a serial port or tcp:// bridge
};

class Session {
 public:
  using WakeFn = std::function<void()>;

  // Subscribes its creator to the lap stream as `consumer` with a ring of `queue_capacity` laps,
  // reachable through laps(); `wake` runs after every lap put in that ring.
  explicit Session(std::size_t queue_capacity = 16, WakeFn wake = {}, std::string consumer = "main");
  ~Session();  // disconnects and joins the I/O thread
  Session(const Session&) = delete;
  Session& operator=(const Session&) = delete;

  LapSubscription& laps() { return *laps_; }
  // Further consumers subscribe here, from any thread, while laps flow (see LapStream).
  LapStream& lap_stream() { return stream_; }

  // Intents, posted to the I/O thread. connect replaces any current connection.
  void connect(SessionConfig config);
  void disconnect();
  void set_scan_hz(double target_hz, CommandCallback done = {});
  void set_ranging_khz(std::uint16_t target_khz, CommandCallback done = {});
  void set_power_down_protection(bool on, CommandCallback done = {});
  void refresh_health(CommandCallback done = {});
  void start_recording(std::string path, CommandCallback done = {});
  void stop_recording(CommandCallback done = {});
  // Every record a recording would hold, live, into `tap` (for MCAP and the WebSocket bridge),
  // beside or without a file recording, and beside other taps. stop_tap(tap) closes that tap;
  // stop_taps closes several in one step on the I/O thread, so no read lands between them and
  // they all end at the same byte (a .ydrec and an MCAP file of one run hold the same laps).
  void start_tap(std::shared_ptr<RecordTap> tap, CommandCallback done = {});
  void stop_tap(std::shared_ptr<RecordTap> tap, CommandCallback done = {});
  void stop_taps(std::vector<std::shared_ptr<RecordTap>> taps, CommandCallback done = {});
  // Empty: back to the model profile's scale. Applies from the next decoded byte.
  void set_distance_scale(std::optional<double> mm_per_count);
  // Reads the unit's bytes the field's way or the manual's way from the next byte on.
  void set_reading(Reading reading);

  // Any thread; a copy under a mutex plus relaxed counter loads: cheap enough for every frame.
  SessionSnapshot snapshot() const;
  // Blocks until `done(snapshot)` holds or the timeout passes; returns the last snapshot seen.
  // For the CLI and tests (the UI polls snapshot() instead).
  SessionSnapshot wait_until(const std::function<bool(const SessionSnapshot&)>& done,
                             std::chrono::milliseconds timeout) const;

  class Impl;

 private:
  // In this order: the I/O thread (impl_) stops before the stream and the rings go.
  LapStream stream_;
  std::unique_ptr<LapSubscription> laps_;
  std::unique_ptr<Impl> impl_;
};

// A one-line JSON-free rendering of a snapshot's state for logs: "scanning: G6 on /dev/pts/3 ...".
std::string describe_snapshot(const SessionSnapshot& snapshot);

}  // namespace ydscope
