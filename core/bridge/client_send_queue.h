#pragma once
// ClientSendQueue: one WebSocket client's bounded queue of outgoing messages.
//
// The message being written sits in a slot of its own: the socket write reads its bytes until it
// completes, so it must never move. (A single deque holding it at the front moved it: erasing the
// oldest waiting message right behind it shifted the front element, under the running write.)
// When the queue is full, the oldest waiting lap (binary Message Data) is dropped and counted, so
// the status message telling a slow client about its drops is not itself dropped by the next
// lap; only a queue of nothing but text messages drops its oldest text. The message in flight is
// never dropped. queued() and queued_bytes() say what it holds (waiting and in flight), so a test
// or a benchmark can see that a client that never reads pins no more than `capacity` messages. Not
// thread-safe: the server's thread owns it.
#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>
#include <deque>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace ydscope::foxglove {

struct OutgoingMessage {
  bool text = false;
  std::string json;                                          // text messages
  std::array<std::uint8_t, 13> header{};                     // binary: Message Data header
  std::shared_ptr<const std::vector<std::uint8_t>> payload;  // binary: shared by every client

  // What the message holds for its client: its bytes on the wire, less the WebSocket framing.
  std::size_t bytes() const { return text ? json.size() : header.size() + (payload ? payload->size() : 0); }
};

class ClientSendQueue {
 public:
  // At most `capacity` messages waiting or in flight (at least 1) before the oldest waiting goes.
  explicit ClientSendQueue(std::size_t capacity) : capacity_(capacity < 1 ? 1 : capacity) {}

  // Queues `message`, dropping the oldest waiting lap (else text) first when full. True if one
  // was dropped.
  bool push(OutgoingMessage message) {
    bool dropped = false;
    if (waiting_.size() + (in_flight_ ? 1 : 0) >= capacity_ && !waiting_.empty()) {
      const auto lap = std::find_if(waiting_.begin(), waiting_.end(), [](const OutgoingMessage& m) { return !m.text; });
      const auto oldest = lap != waiting_.end() ? lap : waiting_.begin();
      bytes_ -= oldest->bytes();
      waiting_.erase(oldest);
      ++dropped_;
      dropped = true;
    }
    bytes_ += message.bytes();
    waiting_.push_back(std::move(message));
    return dropped;
  }

  // The next message to write, now in flight; nullptr when one is in flight already or none waits.
  // The pointer stays valid, and the message unchanged, until end_write().
  const OutgoingMessage* begin_write() {
    if (in_flight_ || waiting_.empty()) return nullptr;
    in_flight_.emplace(std::move(waiting_.front()));
    waiting_.pop_front();
    return &*in_flight_;
  }
  // The write finished (sent or failed).
  void end_write() {
    if (in_flight_) bytes_ -= in_flight_->bytes();
    in_flight_.reset();
  }

  bool writing() const { return in_flight_.has_value(); }
  std::size_t waiting() const { return waiting_.size(); }
  std::uint64_t dropped() const { return dropped_; }
  // Messages held, waiting or in flight (never more than the capacity, or 2 for a capacity of 1:
  // the one in flight and the newest), and their bytes.
  std::size_t queued() const { return waiting_.size() + (in_flight_ ? 1 : 0); }
  std::size_t queued_bytes() const { return bytes_; }

 private:
  std::size_t capacity_;
  std::deque<OutgoingMessage> waiting_;
  std::optional<OutgoingMessage> in_flight_;
  std::uint64_t dropped_ = 0;
  std::size_t bytes_ = 0;
};

}  // namespace ydscope::foxglove
