#include "core/protocol/reply_reader.h"

#include <algorithm>
#include <cstring>

namespace ydscope {

void ReplyReader::reset() {
  state_ = State::Searching;
  header_size_ = 0;
  header_ = {};
  payload_size_ = 0;
  junk_ = 0;
}

void ReplyReader::hunt(std::uint8_t byte) {
  if (header_size_ == 1 && byte != kReplyStart1) {
    ++junk_;  // the lone A5
    header_size_ = 0;
  }
  if (header_size_ == 0 && byte != kReplyStart0) {
    ++junk_;
    return;
  }
  header_bytes_[header_size_++] = byte;
  if (header_size_ == kReplyHeaderSize) header_collected();
}

void ReplyReader::header_collected() {
  const auto header = parse_reply_header(header_bytes_);
  if (header && (header->mode == ReplyMode::Continuous || header->length <= kMaxReplyPayload)) {
    header_ = *header;
    payload_size_ = 0;
    if (header_.mode == ReplyMode::Continuous || header_.length == 0) state_ = State::Complete;
    return;
  }
  // Undefined mode or a length no command answers: the A5 was junk; look again from the next byte.
  const auto held = header_bytes_;
  header_size_ = 0;
  ++junk_;
  for (std::size_t i = 1; i < kReplyHeaderSize; ++i) hunt(held[i]);
}

std::size_t ReplyReader::feed(std::span<const std::uint8_t> bytes) {
  std::size_t used = 0;
  while (used < bytes.size() && state_ == State::Searching) {
    if (header_size_ < kReplyHeaderSize) {
      hunt(bytes[used++]);
    } else {
      const std::size_t take = std::min<std::size_t>(header_.length - payload_size_, bytes.size() - used);
      std::memcpy(payload_.data() + payload_size_, bytes.data() + used, take);
      payload_size_ += take;
      used += take;
      if (payload_size_ == header_.length) state_ = State::Complete;
    }
    if (state_ == State::Searching && junk_ > max_junk_) state_ = State::GaveUp;
  }
  return used;
}

}  // namespace ydscope
