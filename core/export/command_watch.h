#pragma once
// CommandWatch: whether a lidar is spinning up or a command is in flight, read from what the
// diagnostics writer sees (the host->device bytes of a recording or a live tap, and the laps).
// The session says neither in its records, but every command it sends is in the host bytes: after
// A5 60 (scan) the unit spins up until its first lap closes; after any other command the scan is
// stopped (or answering) until a lap closes again. Routine, so /diagnostics says it as a warning,
// not an error, and not as "ok" while no lap comes. A5 60 sent while laps still come (within
// kKeepAliveLapNs of the last one) is the session's keep-alive, not a spin-up. Past kSettleLimitNs it is no longer routine,
// and the writer says what it said before (no complete lap). Plain values, no I/O.
#include <cstdint>
#include <optional>
#include <span>
#include <string>

#include "core/protocol/commands.h"

namespace ydscope {

// Longer than any spin-up (a G6 or TG scans within about 2 s of A5 60) or command sequence.
inline constexpr std::int64_t kSettleLimitNs = 10'000'000'000;
inline constexpr std::int64_t kKeepAliveLapNs = 1'000'000'000;

class CommandWatch {
 public:
  // Host->device bytes recorded at `t_ns` (a command may be split across two records).
  void host_bytes(std::span<const std::uint8_t> bytes, std::int64_t t_ns);
  // A lap closed at `t_ns`: the unit scans, nothing is in flight.
  void lap_closed(std::int64_t t_ns) {
    last_.reset();
    last_lap_t_ns_ = t_ns;
  }

  // Empty while the unit scans, or when the newest command is older than kSettleLimitNs at
  // `now_ns`; else one phrase: "spinning up (scan command sent, no lap yet)" or "command in
  // progress: device info (A5 90)".
  std::optional<std::string> settling(std::int64_t now_ns) const;

 private:
  std::optional<Command> last_;  // the newest command since the last lap
  std::int64_t last_t_ns_ = 0;
  std::optional<std::int64_t> last_lap_t_ns_;
  bool start_byte_pending_ = false;
};

}  // namespace ydscope
