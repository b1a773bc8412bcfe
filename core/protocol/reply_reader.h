#pragma once
// ReplyReader: finds one command reply in incoming bytes. It skips junk until `A5 5A`, reads the
// header, then the payload, and stops right after the reply so the caller keeps whatever follows
// (after A5 60 that is the scan stream). Payloads are bounded by kMaxReplyPayload: a header that
// claims more is treated as junk. It gives up after `max_junk` skipped bytes.
#include <array>
#include <cstddef>
#include <cstdint>
#include <span>

#include "core/protocol/reply.h"

namespace ydscope {

class ReplyReader {
 public:
  enum class State { Searching, Complete, GaveUp };

  explicit ReplyReader(std::size_t max_junk = 4096) : max_junk_(max_junk) {}

  // Consumes bytes up to the end of one reply (or all of them while still searching).
  // Returns how many bytes of `bytes` were used; the rest belong to the caller.
  std::size_t feed(std::span<const std::uint8_t> bytes);

  State state() const { return state_; }
  bool complete() const { return state_ == State::Complete; }
  // Valid when complete().
  const ReplyHeader& header() const { return header_; }
  std::span<const std::uint8_t> payload() const { return {payload_.data(), payload_size_}; }
  std::size_t junk_bytes() const { return junk_; }
  // Ready for the next reply.
  void reset();

 private:
  void hunt(std::uint8_t byte);  // one byte while looking for / collecting the header
  void header_collected();

  std::size_t max_junk_;
  State state_ = State::Searching;
  std::array<std::uint8_t, kReplyHeaderSize> header_bytes_{};
  std::size_t header_size_ = 0;
  ReplyHeader header_;
  std::array<std::uint8_t, kMaxReplyPayload> payload_{};
  std::size_t payload_size_ = 0;
  std::size_t junk_ = 0;
};

}  // namespace ydscope
