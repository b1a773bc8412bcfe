#include "core/session/session_io.h"

#include <algorithm>
#include <ctime>

#include <boost/asio/post.hpp>
#include <boost/asio/redirect_error.hpp>
#include <boost/asio/use_awaitable.hpp>

#include "core/session/read_hold.h"
#include "core/protocol/reply.h"

namespace ydscope {

namespace asio = boost::asio;
using namespace std::chrono_literals;

namespace {
// The continuous reply to A5 60 that precedes the stream.
constexpr std::array<std::uint8_t, kReplyHeaderSize> kScanHeader{0xA5, 0x5A, 0x05, 0x00, 0x00, 0x40, 0x81};
}  // namespace

std::int64_t link_clock_ns() {
  timespec ts{};
  clock_gettime(CLOCK_MONOTONIC, &ts);
  return static_cast<std::int64_t>(ts.tv_sec) * 1'000'000'000 + ts.tv_nsec;
}

SessionIo::SessionIo(asio::io_context& io, SessionCounters& counters)
    : io_(io), counters_(counters), wait_timer_(io), hold_timer_(io) {}

SessionIo::~SessionIo() { detach(); }

void SessionIo::attach(std::unique_ptr<ByteLink> link) {
  link_ = std::move(link);
  ++generation_;
  fault_.clear();
  holding_ = false;  // a hold of the previous link ended with its generation
  set_sink(Sink::Discard);
  device_scanning_ = false;
  write_count_ = 0;
  writing_ = false;
  received_any_ = false;
  start_read();
}

void SessionIo::detach() {
  if (!link_) return;
  ++generation_;  // handlers of the old link are ignored from here on
  link_->close();
  // Aborted handlers of the old link are queued already; destroy it after they have run.
  std::shared_ptr<ByteLink> retired(std::move(link_));
  asio::post(io_, [retired] {});
  device_scanning_ = false;
  set_sink(Sink::Discard);
  wake_waiters();
}

void SessionIo::fail(std::string sentence) { raise_fault(std::move(sentence)); }

void SessionIo::raise_fault(std::string sentence) {
  if (!fault_.empty()) return;
  fault_ = std::move(sentence);
  detach();
  if (on_fault_) on_fault_();
}

void SessionIo::wake_waiters() { wait_timer_.cancel(); }

void SessionIo::start_read() {
  if (!link_) return;
  const std::uint64_t generation = generation_;
  link_->async_read_some(
      buffer_, [this, generation](const boost::system::error_code& ec, std::size_t n) { on_read(generation, ec, n); });
}

void SessionIo::on_read(std::uint64_t generation, const boost::system::error_code& ec, std::size_t n) {
  if (generation != generation_) return;  // a closed link's last word
  if (ec) {
    const std::string what = link_ ? link_->describe() : std::string("the port");
    const bool closed = ec == asio::error::eof || ec == asio::error::connection_reset;
    if (closed && !received_any_)  // closed at once: turned away, not unplugged
      raise_fault("the link to " + what +
                  " closed before it sent a byte: another program may be connected "
                  "to it already (a virtual lidar or a ser2net port serves one host at a time); close that one "
                  "and try again");
    else if (ec == asio::error::eof)
      raise_fault("the link to " + what + " closed (device unplugged or bridge gone)");
    else
      raise_fault("reading " + what + " failed: " + ec.message() + " (device unplugged?)");
    return;
  }
  const std::int64_t now = link_clock_ns();
  counters_.add_received(n, now);
  last_rx_ns_ = now;
  received_any_ = true;
  const std::span<const std::uint8_t> bytes(buffer_.data(), n);
  if (on_wire_) on_wire_(false, bytes, now);
  route(bytes, now);
  read_on(now);
}

void SessionIo::read_on(std::int64_t now) {
  if (!link_) return;
  const auto hold = sink_ == Sink::Stream
                        ? read_hold({now, stream_outlook_, counters_.bytes_per_s(), link_->line_bytes_per_s()})
                        : std::chrono::nanoseconds(0);
  if (hold.count() == 0) {
    start_read();
    return;
  }
  link_->stop_watching_input();
  holding_ = true;
  hold_timer_.expires_after(hold);
  const std::uint64_t generation = generation_;
  hold_timer_.async_wait([this, generation](const boost::system::error_code&) {
    if (generation != generation_ || !holding_) return;
    holding_ = false;
    start_read();
  });
}

void SessionIo::end_hold() {
  if (!holding_) return;
  holding_ = false;
  hold_timer_.cancel();
  start_read();
}

void SessionIo::set_sink(Sink sink) {
  sink_ = sink;
  // Replies and drains must see every byte as it comes.
  if (sink != Sink::Stream) end_hold();
}

void SessionIo::route(std::span<const std::uint8_t> bytes, std::int64_t now) {
  if (sink_ == Sink::Discard || sink_ == Sink::Reply) unsolicited_.feed(bytes, now);
  while (!bytes.empty()) {
    switch (sink_) {
      case Sink::Discard: counters_.add_drained(bytes.size()); return;
      case Sink::Stream:
        if (on_stream_) stream_outlook_ = on_stream_(bytes, now);
        return;
      case Sink::ScanHeader: {
        // Match the header byte by byte; on the first mismatch everything goes to the decoder,
        // which resynchronises on its own (so a stream without the header still decodes).
        std::size_t used = 0;
        while (used < bytes.size() && scan_header_matched_ < kScanHeader.size() &&
               bytes[used] == kScanHeader[scan_header_matched_]) {
          ++used;
          ++scan_header_matched_;
        }
        if (scan_header_matched_ == kScanHeader.size()) {
          set_sink(Sink::Stream);
          bytes = bytes.subspan(used);
          break;
        }
        if (used == bytes.size()) return;  // header still arriving
        set_sink(Sink::Stream);
        if (on_stream_ && scan_header_matched_ > 0)
          on_stream_(std::span<const std::uint8_t>(kScanHeader.data(), scan_header_matched_ - used), now);
        // The part matched in this chunk is still at the start of `bytes`: hand it all over.
        if (on_stream_) stream_outlook_ = on_stream_(bytes, now);
        return;
      }
      case Sink::Reply: {
        reply_bytes_seen_ += bytes.size();
        const std::size_t used = reply_.feed(bytes);
        bytes = bytes.subspan(used);
        if (reply_.complete()) {
          if (reply_matches(reply_.header(), awaited_)) {
            reply_done_ = true;
            set_sink(Sink::Discard);
            wake_waiters();
          } else {
            reply_.reset();  // a stale or foreign reply: keep looking
          }
        } else if (reply_.state() == ReplyReader::State::GaveUp) {
          set_sink(Sink::Discard);
          wake_waiters();
        }
        break;
      }
    }
  }
}

bool SessionIo::send(Command command) {
  if (!link_) return false;
  const bool keepalive = command == Command::Scan && keepalive_allowed_;
  if (device_scanning_ && command != Command::Stop && !keepalive) {
    counters_.add_refused();
    return false;
  }
  if (command == Command::Scan) device_scanning_ = true;
  if (command == Command::Stop || command == Command::RestartG1 || command == Command::RestartG6TG)
    device_scanning_ = false;
  if (write_count_ == kWriteSlots) {
    raise_fault("writing to " + link_->describe() + " is stuck (commands piled up unsent)");
    return false;
  }
  writes_[(write_head_ + write_count_) % kWriteSlots] = encode_command(command);
  ++write_count_;
  if (!writing_) start_write();
  return true;
}

void SessionIo::start_write() {
  if (!link_ || write_count_ == 0) {
    writing_ = false;
    return;
  }
  writing_ = true;
  const std::span<const std::uint8_t> bytes(writes_[write_head_]);
  if (on_wire_) on_wire_(true, bytes, link_clock_ns());
  const std::uint64_t generation = generation_;
  link_->async_write(bytes, [this, generation](const boost::system::error_code& ec, std::size_t n) {
    if (generation != generation_) return;
    if (ec) {
      raise_fault("writing to " + (link_ ? link_->describe() : std::string("the port")) + " failed: " + ec.message() +
                  " (device unplugged?)");
      return;
    }
    counters_.add_sent(n);
    write_head_ = (write_head_ + 1) % kWriteSlots;
    --write_count_;
    start_write();
  });
}

asio::awaitable<bool> SessionIo::sleep(std::chrono::milliseconds duration) {
  const std::uint64_t generation = generation_;
  wait_timer_.expires_after(duration);
  boost::system::error_code ec;
  co_await wait_timer_.async_wait(asio::redirect_error(asio::use_awaitable, ec));
  co_return !ec && generation == generation_;
}

asio::awaitable<void> SessionIo::drain(std::chrono::milliseconds quiet, std::chrono::milliseconds limit) {
  set_sink(Sink::Discard);
  const std::int64_t start = link_clock_ns();
  const std::int64_t quiet_ns = std::chrono::nanoseconds(quiet).count();
  const std::int64_t limit_ns = std::chrono::nanoseconds(limit).count();
  while (link_) {
    const std::uint64_t generation = generation_;
    wait_timer_.expires_after(quiet);
    boost::system::error_code ec;
    co_await wait_timer_.async_wait(asio::redirect_error(asio::use_awaitable, ec));
    if (generation != generation_) co_return;
    const std::int64_t now = link_clock_ns();
    if (now - std::max(last_rx_ns_, start) >= quiet_ns || now - start >= limit_ns) co_return;
  }
}

asio::awaitable<Exchange> SessionIo::exchange(Command command, std::chrono::milliseconds timeout) {
  Exchange result;
  if (!link_) {
    result.outcome = Exchange::Outcome::LinkLost;
    co_return result;
  }
  const ReplySpec spec = reply_spec(command);
  if (spec.mode == ReplyMode::Single) {
    reply_.reset();
    awaited_ = command;
    reply_done_ = false;
    reply_bytes_seen_ = 0;
    set_sink(Sink::Reply);
  }
  if (!send(command)) {
    set_sink(Sink::Discard);
    result.outcome = link_ ? Exchange::Outcome::Refused : Exchange::Outcome::LinkLost;
    co_return result;
  }
  if (spec.mode != ReplyMode::Single) {
    result.outcome = Exchange::Outcome::Reply;
    co_return result;
  }
  const std::uint64_t generation = generation_;
  wait_timer_.expires_after(timeout);
  boost::system::error_code ec;
  co_await wait_timer_.async_wait(asio::redirect_error(asio::use_awaitable, ec));
  if (sink_ == Sink::Reply) set_sink(Sink::Discard);
  result.bytes_seen = reply_bytes_seen_;
  if (generation != generation_ || !link_) {
    result.outcome = Exchange::Outcome::LinkLost;
  } else if (reply_done_) {
    result.outcome = Exchange::Outcome::Reply;
    const auto payload = reply_.payload();
    result.payload_size = std::min(payload.size(), result.payload.size());
    std::copy_n(payload.begin(), result.payload_size, result.payload.begin());
  } else {
    result.outcome = reply_bytes_seen_ > 0 ? Exchange::Outcome::Garbled : Exchange::Outcome::NoReply;
  }
  co_return result;
}

bool SessionIo::start_stream() {
  scan_header_matched_ = 0;
  const Sink previous = sink_;
  set_sink(Sink::ScanHeader);
  if (!send(Command::Scan)) {
    set_sink(previous);
    return false;
  }
  return true;
}

void SessionIo::stop_stream() { set_sink(Sink::Discard); }

}  // namespace ydscope
