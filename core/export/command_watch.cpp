#include "core/export/command_watch.h"

#include <cstdio>

namespace ydscope {

void CommandWatch::host_bytes(std::span<const std::uint8_t> bytes, std::int64_t t_ns) {
  for (const std::uint8_t byte : bytes) {
    if (start_byte_pending_) {
      start_byte_pending_ = false;
      if (const auto command = command_from_code(byte)) {
        const bool keep_alive =
            *command == Command::Scan && !last_ && last_lap_t_ns_ && t_ns - *last_lap_t_ns_ <= kKeepAliveLapNs;
        if (keep_alive) continue;
        last_ = command;
        last_t_ns_ = t_ns;
        continue;
      }
    }
    start_byte_pending_ = byte == kCommandStart;
  }
}

std::optional<std::string> CommandWatch::settling(std::int64_t now_ns) const {
  if (!last_ || now_ns - last_t_ns_ > kSettleLimitNs) return std::nullopt;
  if (*last_ == Command::Scan) return "spinning up (scan command sent, no lap yet)";
  char code[8];
  std::snprintf(code, sizeof code, "A5 %02X", static_cast<unsigned>(*last_));
  return "command in progress: " + std::string(command_name(*last_)) + " (" + code + ")";
}

}  // namespace ydscope
