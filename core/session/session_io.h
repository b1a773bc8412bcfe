#pragma once
// SessionIo: the byte layer of a Session, on the I/O thread only. It owns the open link, runs the
// one perpetual read into a fixed buffer, routes what arrives (discard while draining, a reply
// being awaited, or the scan stream), queues writes, and is the ONE place that decides whether a
// command may be sent: while the device scans only A5 65 goes out (and A5 60 as the power-down
// keepalive when that mode is on). Its coroutines are the steps the manuals prescribe: drain,
// exchange a command for its reply with a timeout, start the scan stream.
#include <array>
#include <chrono>
#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <utility>  // before asio's awaitable.hpp, which uses std::exchange without including it

#include <boost/asio/awaitable.hpp>
#include <boost/asio/io_context.hpp>
#include <boost/asio/steady_timer.hpp>

#include "core/protocol/stream_diagnosis.h"
#include "core/link/byte_link.h"
#include "core/session/session_counters.h"
#include "core/protocol/commands.h"
#include "core/protocol/lap_end_forecast.h"
#include "core/protocol/reply_reader.h"

namespace ydscope {

// CLOCK_MONOTONIC in ns: the receive time stamped on laps (and the virtual lidar's clock).
std::int64_t link_clock_ns();

// What one command exchange gave: the payload, or why there is none.
struct Exchange {
  enum class Outcome { Reply, NoReply, Garbled, Refused, LinkLost };
  Outcome outcome = Outcome::NoReply;
  std::array<std::uint8_t, kMaxReplyPayload> payload{};
  std::size_t payload_size = 0;
  std::size_t bytes_seen = 0;  // bytes that arrived while waiting (wrong baud shows up here)
  std::span<const std::uint8_t> bytes() const { return {payload.data(), payload_size}; }
  bool ok() const { return outcome == Outcome::Reply; }
};

class SessionIo {
 public:
  // Takes stream bytes; returns how many more can arrive before its consumer needs to see them.
  // Mid-lap, reading is held off accordingly (read_hold.h).
  using StreamFn = std::function<LapEndOutlook(std::span<const std::uint8_t>, std::int64_t rx_ns)>;
  using WireFn = std::function<void(bool outgoing, std::span<const std::uint8_t>, std::int64_t ns)>;
  using FaultFn = std::function<void()>;

  static constexpr std::size_t kReadBufferSize = 4096;

  SessionIo(boost::asio::io_context& io, SessionCounters& counters);
  ~SessionIo();

  // Takes the link and starts reading. The previous link, if any, must have been detached.
  void attach(std::unique_ptr<ByteLink> link);
  // Closes the link; pending waits end. Safe to call twice.
  void detach();
  bool attached() const { return link_ != nullptr; }
  ByteLink* link() { return link_.get(); }

  // The fault that ended the link (read/write error, EOF), as a sentence; empty while healthy.
  const std::string& fault() const { return fault_; }
  // Called on the I/O thread when a fault is first seen (the supervisor wakes up).
  void on_fault(FaultFn fn) { on_fault_ = std::move(fn); }
  // Marks the link faulty from outside (stall watchdog) and closes it.
  void fail(std::string sentence);

  void on_stream(StreamFn fn) { on_stream_ = std::move(fn); }
  // Every byte in and out, for the recorder. Empty: nothing is recorded.
  void on_wire(WireFn fn) { on_wire_ = std::move(fn); }

  // True between a sent A5 60 and a sent A5 65 (or restart): the device is streaming.
  bool device_scanning() const { return device_scanning_; }
  // Power-down protection is on: A5 60 may be repeated while scanning as the keepalive.
  void allow_scan_keepalive(bool allow) { keepalive_allowed_ = allow; }

  // The gate: sends `command` unless the device scans and it is not A5 65 (or the allowed keepalive).
  // Refusals are counted (SessionCounters::refused_commands) and return false; they are bugs.
  bool send(Command command);

  // Discards input until the line has been quiet for `quiet` or `limit` has passed.
  boost::asio::awaitable<void> drain(std::chrono::milliseconds quiet, std::chrono::milliseconds limit);
  // Sends `command` (gated) and waits up to `timeout` for its reply; commands without a reply
  // complete once sent. Bytes after the reply are discarded.
  boost::asio::awaitable<Exchange> exchange(Command command, std::chrono::milliseconds timeout);
  // Sends A5 60 and routes the stream to on_stream, stripping the A5 5A 05 00 00 40 81 header when
  // it comes (a stream without it is decoded all the same).
  bool start_stream();
  // Routes incoming bytes to on_stream without sending anything (a replay has no device to ask).
  void listen_stream() { sink_ = Sink::Stream; }
  // Back to discarding (after A5 65).
  void stop_stream();
  // The bytes that came while no scan was being decoded (drains, hunts for a reply): when a
  // device does not answer but bytes flow, they say why (a wrong baud, another layout).
  const StreamDiagnosis& unsolicited() const { return unsolicited_; }
  void forget_unsolicited() { unsolicited_.reset(); }
  // A timer wait that ends early on a fault or detach; false when it ended early.
  boost::asio::awaitable<bool> sleep(std::chrono::milliseconds duration);

 private:
  enum class Sink { Discard, Reply, ScanHeader, Stream };

  void start_read();
  void on_read(std::uint64_t generation, const boost::system::error_code& ec, std::size_t n);
  void route(std::span<const std::uint8_t> bytes, std::int64_t now);
  void set_sink(Sink sink);
  // After stream bytes: read again at once, or hold off for what the forecast allows.
  void read_on(std::int64_t now);
  void end_hold();
  void start_write();
  void raise_fault(std::string sentence);
  void wake_waiters();

  boost::asio::io_context& io_;
  SessionCounters& counters_;
  std::unique_ptr<ByteLink> link_;
  std::uint64_t generation_ = 0;
  std::array<std::uint8_t, kReadBufferSize> buffer_{};
  std::string fault_;
  FaultFn on_fault_;
  StreamFn on_stream_;
  WireFn on_wire_;

  Sink sink_ = Sink::Discard;
  ReplyReader reply_{};
  Command awaited_ = Command::Stop;
  bool reply_done_ = false;
  std::size_t reply_bytes_seen_ = 0;
  StreamDiagnosis unsolicited_;
  std::size_t scan_header_matched_ = 0;
  LapEndOutlook stream_outlook_{};  // what the stream consumer last said can arrive unseen
  bool holding_ = false;            // reading is held off; hold_timer_ restarts it
  std::int64_t last_rx_ns_ = 0;

  bool device_scanning_ = false;
  bool keepalive_allowed_ = false;

  // Commands are two bytes; a small ring keeps them alive until written, one write at a time.
  static constexpr std::size_t kWriteSlots = 16;
  std::array<std::array<std::uint8_t, 2>, kWriteSlots> writes_{};
  std::size_t write_head_ = 0;
  std::size_t write_count_ = 0;
  bool received_any_ = false;  // a link that closes before its first byte turned us away
  bool writing_ = false;

  // One timer for whichever coroutine step waits (the session runs one step at a time).
  boost::asio::steady_timer wait_timer_;
  boost::asio::steady_timer hold_timer_;
};

}  // namespace ydscope
