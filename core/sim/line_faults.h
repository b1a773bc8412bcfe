#pragma once
// What the virtual lidar's line does wrong, as FaultConfig asks: scan packets lost or discarded by
// a stall, sample bytes flipped, outgoing bytes dropped, junk in front of replies; and the
// FaultCounters that say what was injected. VirtualLidar makes the packets and replies; this
// decides what of them reaches the line. Each fault draws from a generator of its own, so
// switching one on never moves where another strikes.
#include <cstddef>
#include <cstdint>
#include <limits>
#include <optional>
#include <span>
#include <vector>

#include "core/sim/faults.h"

namespace ydscope {

// What became of one scan packet on its way to the line.
struct PacketFate {
  bool lost = false;       // not sent: the lost-packet fault, or a stall
  bool corrupted = false;  // sent with a broken checksum
  bool altered = false;    // sent with flips that cancel in its checksum (see TruthPacket::altered)
};

class LineFaults {
 public:
  static constexpr std::int64_t kNever = std::numeric_limits<std::int64_t>::max();

  LineFaults(const FaultConfig& config, std::uint64_t seed);

  const FaultConfig& config() const { return config_; }
  const FaultCounters& counters() const { return counters_; }
  // New faults from now on; `scanning_since`, while the device scans, restarts the periodic stalls' schedule there.
  void set_config(const FaultConfig& config, std::optional<std::int64_t> scanning_since);

  // A scan packet made ready at ready_ns, its samples from `samples_at`: lost, stalled, or sent
  // with its sample bytes flipped in place. The zero packet is never lost (stalls still take it).
  PacketFate apply(std::vector<std::uint8_t>& packet, std::size_t samples_at, bool zero_packet, std::int64_t ready_ns);
  // Removes the dropped bytes from out[base..] in place; each zero packet's end offset from
  // zero_ends[zero_base..] moves back by the bytes removed before it.
  void drop_bytes(std::vector<std::uint8_t>& out, std::size_t base, std::vector<std::size_t>* zero_ends,
                  std::size_t zero_base);
  // A reply due at now_ns as it goes out: the junk in front, then the reply. False (and nothing
  // appended) when a stall discards it.
  bool frame_reply(std::span<const std::uint8_t> reply, std::int64_t now_ns, std::vector<std::uint8_t>& out);

  // Nothing goes out in [from_ns, from_ns + duration_ns).
  void stall(std::int64_t from_ns, std::int64_t duration_ns);
  // Periodic stalls run while the device scans: armed at the start of a scan, disarmed at its end.
  void arm_periodic_stalls(std::int64_t scan_start_ns);
  void disarm_periodic_stalls() { next_periodic_stall_ns_ = kNever; }
  // The next periodic stall's start, or kNever.
  std::int64_t next_periodic_stall_ns() const { return next_periodic_stall_ns_; }
  // The start of a periodic stall due by t_ns, its schedule moved on to the next one; or nothing.
  std::optional<std::int64_t> take_due_stall(std::int64_t t_ns);
  // Power-on: no stall in progress or scheduled.
  void clear_stalls();

 private:
  bool in_stall(std::int64_t t_ns) const { return t_ns >= stall_from_ns_ && t_ns < stall_until_ns_; }

  FaultConfig config_;
  FaultCounters counters_;
  FaultRandom corrupt_random_;
  FaultRandom drop_random_;
  FaultRandom lost_random_;
  FaultRandom junk_random_;
  std::int64_t stall_from_ns_ = 0;
  std::int64_t stall_until_ns_ = 0;
  std::int64_t next_periodic_stall_ns_ = kNever;
};

}  // namespace ydscope
