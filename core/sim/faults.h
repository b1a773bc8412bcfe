#pragma once
// Faults the virtual lidar can inject, and what it counts, so a test can compare what the host saw
// with what was injected. Every decision comes from a seeded generator of its own per fault kind,
// so switching one fault on never changes where another one strikes.
#include <cstdint>

namespace ydscope {

struct FaultConfig {
  // Probability per sample byte of a scan packet that one of its bits is flipped. Only sample bytes
  // are touched, so a corrupted packet keeps its framing and fails exactly its checksum.
  double corrupt_byte_rate = 0.0;
  // Probability per outgoing byte (packets and replies) that it never reaches the line.
  double drop_byte_rate = 0.0;
  // Probability per non-zero scan packet that it is not sent at all (its CT still enters G1's
  // CRC8, so that lap's CRC verdict fails on the host).
  double lost_packet_rate = 0.0;
  // Periodic stall: every stall_every_ms of scanning the device sends nothing for stall_ms
  // (packets and replies due in that window are discarded). 0 = off. See also VirtualLidar::stall.
  std::int64_t stall_ms = 0;
  std::int64_t stall_every_ms = 0;
  // Health bits raised: G1 status bits (A5 92 and CT index 3); on G6/TG the A5 91 status becomes
  // 2 (error) with these bits as the error code.
  std::uint8_t health_bits = 0;
  // Random bytes (never A5, never AA) sent in front of every reply header.
  std::uint32_t junk_before_reply = 0;
  // A motor that does not hold its set rate: it runs scan_hz_offset Hz off it, and wanders about
  // that by up to scan_hz_wobble Hz (a sine of period kScanWobblePeriodNs). The ranging clock is
  // unaffected, so a lap holds ranging Hz / actual rate samples; G1's CT reports the actual rate.
  double scan_hz_offset = 0.0;
  double scan_hz_wobble = 0.0;
  // Something in front of the window (a bracket, a cable, dirt): samples whose direction lies in
  // the sector from blocked_from_deg clockwise over blocked_width_deg come back as no return.
  // Width 0 = off.
  double blocked_from_deg = 0.0;
  double blocked_width_deg = 0.0;
};

inline constexpr std::int64_t kScanWobblePeriodNs = 2'000'000'000;

struct FaultCounters {
  std::uint64_t corrupted_bytes = 0;    // sample bytes with a flipped bit
  std::uint64_t corrupted_packets = 0;  // packets whose checksum the flips really broke
  std::uint64_t dropped_bytes = 0;
  std::uint64_t lost_packets = 0;
  std::uint64_t stalls = 0;           // stall windows begun
  std::uint64_t stalled_packets = 0;  // scan packets discarded by a stall
  std::uint64_t stalled_bytes = 0;    // all bytes (packets and replies) discarded by a stall
  std::uint64_t junk_bytes = 0;
  std::uint64_t blocked_samples = 0;  // samples the blocked sector sent with no return
};

// A small deterministic generator (splitmix64): the same seed gives the same faults on every run.
class FaultRandom {
 public:
  explicit FaultRandom(std::uint64_t seed) : state_(seed) {}
  std::uint64_t next();
  // True with probability p (p <= 0 never draws, so an off fault costs nothing and shifts nothing).
  bool chance(double p);
  std::uint32_t below(std::uint32_t n);  // uniform in [0, n)

 private:
  std::uint64_t state_;
};

}  // namespace ydscope
