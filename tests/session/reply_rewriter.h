#pragma once
// ReplyRewriter: a ByteLink around another that rewrites payload bytes of the replies to chosen
// commands on their way to the host (a device whose answers lie), and counts the commands sent.
#include <algorithm>
#include <cstdint>
#include <map>
#include <memory>
#include <string>

#include "core/link/byte_link.h"

namespace ydscope::test {

// Rewrites payload bytes of the replies to chosen commands: lies[code][offset] = value. Also
// counts the commands the host sent, by code.
class ReplyRewriter final : public ByteLink {
 public:
  using Lies = std::map<std::uint8_t, std::map<std::size_t, std::uint8_t>>;
  ReplyRewriter(std::unique_ptr<ByteLink> inner, Lies lies, std::map<std::uint8_t, int>& sent)
      : inner_(std::move(inner)), lies_(std::move(lies)), sent_(sent) {}

  void async_read_some(std::span<std::uint8_t> buffer, IoHandler handler) override {
    inner_->async_read_some(buffer, [this, buffer, handler](const boost::system::error_code& ec, std::size_t n) {
      for (std::size_t i = 0; i < n; ++i) rewrite(buffer[i]);
      handler(ec, n);
    });
  }
  void async_write(std::span<const std::uint8_t> bytes, IoHandler handler) override {
    for (std::size_t i = 0; i + 1 < bytes.size(); ++i)
      if (bytes[i] == 0xA5) {
        last_command_ = bytes[i + 1];
        ++sent_[last_command_];
      }
    inner_->async_write(bytes, std::move(handler));
  }
  void close() override { inner_->close(); }
  bool set_baud(std::uint32_t baud, std::string& error) override { return inner_->set_baud(baud, error); }
  bool accepts_commands() const override { return true; }
  std::string describe() const override { return inner_->describe(); }

 private:
  // Reply bytes are counted from the A5 of "A5 5A": 7 header bytes (the length in bytes 2-5,
  // low 30 bits), then the payload.
  void rewrite(std::uint8_t& byte) {
    if (at_ == 0) {
      if (previous_ == 0xA5 && byte == 0x5A) {
        at_ = 2;
        length_ = 0;
      }
      previous_ = byte;
      return;
    }
    if (at_ >= 2 && at_ < 6) length_ |= static_cast<std::uint32_t>(byte) << (8 * (at_ - 2));
    if (at_ >= 7) {
      const auto lie = lies_.find(last_command_);
      if (lie != lies_.end())
        if (const auto value = lie->second.find(at_ - 7); value != lie->second.end()) byte = value->second;
    }
    previous_ = byte;
    ++at_;
    if (at_ >= 7 + std::min<std::uint32_t>(length_ & 0x3FFFFFFF, 20)) {
      at_ = 0;
      previous_ = 0;
    }
  }

  std::unique_ptr<ByteLink> inner_;
  Lies lies_;
  std::map<std::uint8_t, int>& sent_;
  std::uint8_t last_command_ = 0;
  std::uint8_t previous_ = 0;
  std::size_t at_ = 0;
  std::uint32_t length_ = 0;
};

}  // namespace ydscope::test
