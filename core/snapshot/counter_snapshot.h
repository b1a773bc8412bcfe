#pragma once
// The session's counters as any thread reads them: plain numbers, so the snapshot that carries them
// needs none of the atomics the I/O thread counts with (core/session/session_counters.h).
#include <cstdint>
#include <optional>

namespace ydscope {

struct CounterSnapshot {
  std::uint64_t bytes_received = 0;
  std::uint64_t bytes_sent = 0;
  std::uint64_t reads = 0;             // read completions (bytes_received / reads = bytes per wakeup)
  std::uint64_t packets = 0;           // valid scan packets
  std::uint64_t zero_packets = 0;      // of which CT bit 0 was set
  std::uint64_t laps = 0;              // laps pushed or dropped
  std::uint64_t checksum_errors = 0;   // scan packets dropped for a bad XOR checksum
  std::uint64_t resync_bytes = 0;      // bytes skipped while hunting a packet header
  std::uint64_t crc8_failures = 0;     // G1 laps whose LastCRC disagreed
  std::uint64_t cut_points = 0;        // points cut from laps longer than Lap::kMaxPoints
  std::uint64_t drained_bytes = 0;     // bytes discarded while draining before a command
  std::uint64_t reconnects = 0;        // links reopened after a fault
  std::uint64_t refused_commands = 0;  // commands the session refused to send while scanning (bugs)
  double bytes_per_s = 0;
  double packets_per_s = 0;
  double laps_per_s = 0;
  std::optional<double> seconds_since_last_byte;  // empty before the first byte
};

}  // namespace ydscope
