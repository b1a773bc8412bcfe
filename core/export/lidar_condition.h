#pragma once
// What /diagnostics says about a lidar: one level from its state now (a fault five minutes ago
// is not a fault now), and a message naming what set that level, so the words never say "ok"
// beside a warning. Plain values, no I/O: the encoder fills them from its records.
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace ydscope {

// Checksum errors and CRC8 mismatches count against the level for this long.
inline constexpr std::int64_t kConditionWindowNs = 5'000'000'000;

struct LidarCondition {
  // The link is down (the session's link_fault): why, and what it is doing about it.
  std::optional<std::string> link_fault;
  std::optional<std::int64_t> quiet_ns;      // since the device's last byte; empty: none came yet
  std::optional<std::string> health;         // the last health answer ("ok", "error (code 0x0012)")
  std::uint64_t recent_checksum_errors = 0;  // within kConditionWindowNs
  std::uint64_t recent_crc_mismatches = 0;
  bool no_recent_lap = false;  // bytes came, but no lap closed in the last report period
  // The unit spins up or a command is in flight (command_watch.h): routine, a warning that says
  // so, in place of "no complete lap".
  std::optional<std::string> settling;
  // Sectors empty while the rest of the turn sees returns, each "blocked 40°–75° for 12 s"
  // (core/analysis/dropout_ring.h).
  std::vector<std::string> blocked_sectors;
};

struct LidarVerdict {
  std::uint8_t level = 0;  // diagnostic_msgs/DiagnosticStatus: 0 OK, 1 WARN, 2 ERROR
  std::string message;     // the reasons for the level, worst first; "ok; health: ok" at 0
};

LidarVerdict judge_lidar(const LidarCondition& condition);

}  // namespace ydscope
