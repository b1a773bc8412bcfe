#include "core/sim/line_faults.h"

#include "core/protocol/commands.h"
#include "core/protocol/scan_packet.h"

namespace ydscope {
namespace {

// Each fault kind's generator is the seed with a salt of its own.
constexpr std::uint64_t kCorruptSalt = 0xC0AA;
constexpr std::uint64_t kDropSalt = 0xD40F;
constexpr std::uint64_t kLostSalt = 0x1057;
constexpr std::uint64_t kJunkSalt = 0x3A4C;

constexpr std::int64_t kNsPerMs = 1'000'000;

}  // namespace

LineFaults::LineFaults(const FaultConfig& config, std::uint64_t seed)
    : config_(config),
      corrupt_random_(seed ^ kCorruptSalt),
      drop_random_(seed ^ kDropSalt),
      lost_random_(seed ^ kLostSalt),
      junk_random_(seed ^ kJunkSalt) {}

void LineFaults::set_config(const FaultConfig& config, std::optional<std::int64_t> scanning_since) {
  config_ = config;
  if (scanning_since)
    arm_periodic_stalls(*scanning_since);
  else
    disarm_periodic_stalls();
}

PacketFate LineFaults::apply(std::vector<std::uint8_t>& packet, std::size_t samples_at, bool zero_packet,
                             std::int64_t ready_ns) {
  PacketFate fate;
  if (in_stall(ready_ns)) {
    ++counters_.stalled_packets;
    counters_.stalled_bytes += packet.size();
    fate.lost = true;
    return fate;
  }
  if (!zero_packet && lost_random_.chance(config_.lost_packet_rate)) {
    ++counters_.lost_packets;
    fate.lost = true;
    return fate;
  }
  std::uint8_t lane_flips[2] = {0, 0};  // the checksum XORs u16 words: low and high byte lanes
  const std::uint64_t corrupted_before = counters_.corrupted_bytes;
  for (std::size_t i = samples_at; i < packet.size(); ++i) {
    if (!corrupt_random_.chance(config_.corrupt_byte_rate)) continue;
    const auto flip = static_cast<std::uint8_t>(1u << corrupt_random_.below(8));
    packet[i] ^= flip;
    lane_flips[(i - samples_at) % 2] ^= flip;
    ++counters_.corrupted_bytes;
  }
  if (lane_flips[0] || lane_flips[1]) {
    ++counters_.corrupted_packets;
    fate.corrupted = true;
  } else {
    fate.altered = counters_.corrupted_bytes != corrupted_before;
  }
  return fate;
}

void LineFaults::drop_bytes(std::vector<std::uint8_t>& out, std::size_t base, std::vector<std::size_t>* zero_ends,
                            std::size_t zero_base) {
  if (config_.drop_byte_rate <= 0.0) return;
  std::size_t write = base;
  std::size_t next_zero = zero_base;
  for (std::size_t read = base; read < out.size(); ++read) {
    if (drop_random_.chance(config_.drop_byte_rate))
      ++counters_.dropped_bytes;
    else
      out[write++] = out[read];
    while (zero_ends && next_zero < zero_ends->size() && (*zero_ends)[next_zero] == read + 1)
      (*zero_ends)[next_zero++] = write;
  }
  out.resize(write);
}

bool LineFaults::frame_reply(std::span<const std::uint8_t> reply, std::int64_t now_ns, std::vector<std::uint8_t>& out) {
  const std::size_t base = out.size();
  for (std::uint32_t i = 0; i < config_.junk_before_reply; ++i) {
    std::uint8_t junk = 0;
    do {  // never a byte a host could take for the start of a reply or a packet
      junk = static_cast<std::uint8_t>(junk_random_.below(256));
    } while (junk == kCommandStart || junk == kPacketHeader0);
    out.push_back(junk);
  }
  out.insert(out.end(), reply.begin(), reply.end());
  if (in_stall(now_ns)) {
    counters_.stalled_bytes += out.size() - base;
    out.resize(base);
    return false;
  }
  counters_.junk_bytes += config_.junk_before_reply;
  return true;
}

void LineFaults::stall(std::int64_t from_ns, std::int64_t duration_ns) {
  stall_from_ns_ = from_ns;
  stall_until_ns_ = from_ns + duration_ns;
  ++counters_.stalls;
}

void LineFaults::arm_periodic_stalls(std::int64_t scan_start_ns) {
  next_periodic_stall_ns_ =
      config_.stall_ms > 0 && config_.stall_every_ms > 0 ? scan_start_ns + config_.stall_every_ms * kNsPerMs : kNever;
}

std::optional<std::int64_t> LineFaults::take_due_stall(std::int64_t t_ns) {
  if (next_periodic_stall_ns_ > t_ns) return std::nullopt;
  const std::int64_t from = next_periodic_stall_ns_;
  next_periodic_stall_ns_ += config_.stall_every_ms * kNsPerMs;
  return from;
}

void LineFaults::clear_stalls() {
  stall_from_ns_ = stall_until_ns_ = 0;
  next_periodic_stall_ns_ = kNever;
}

}  // namespace ydscope
