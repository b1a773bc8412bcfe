#pragma once
// ClientSendQueue: one WebSocket client's bounded queue of outgoing messages.
//
// The message being written sits in a slot of its own: the socket write reads its bytes until it
// completes, so it must never move. (A single deque holding it at the front moved it: erasing the
// oldest waiting message right behind it shifted the front element, under the running write.)
// When the queue is full, the oldest waiting lap (binary Message Data) is dropped and counted, so
// the status message telling a slow client about its drops is not itself dropped by the next
// lap; only a queue of nothing but text messages drops its oldest text. The message in flight is
// never dropped. Not thread-safe: the server's thread owns it.
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
      waiting_.erase(lap != waiting_.end() ? lap : waiting_.begin());
      ++dropped_;
      dropped = true;
    }
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
  void end_write() { in_flight_.reset(); }

  bool writing() const { return in_flight_.has_value(); }
  std::size_t waiting() const { return waiting_.size(); }
  std::uint64_t dropped() const { return dropped_; }

 private:
  std::size_t capacity_;
  std::deque<OutgoingMessage> waiting_;
  std::optional<OutgoingMessage> in_flight_;
  std::uint64_t dropped_ = 0;
};

}  // namespace ydscope::foxglove
