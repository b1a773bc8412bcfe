#pragma once
// Delivery: how the bytes the virtual lidar's line has carried reach the host, as a USB-serial
// bridge hands them over. A host reads whatever has arrived, so where reads split the stream is
// set by the bridge, not by the device:
//   Whole   as soon as the line has carried them, one write per reply or packet (a host that keeps
//           up reads whole packets) — what the virtual lidar always did.
//   Burst   a CP210x/CH340 fills a USB packet of `burst_bytes` and sends it; what is left over is
//           sent when its latency timer (`interval_ns`) runs out. So the host gets full bursts
//           at every tick of the interval and a short rest one quiet interval later.
//   Random  writes of 1..max_piece bytes (seeded), each after the line could have carried it, so
//           headers and packets are split anywhere.
// No bytes are lost, added or reordered by any model; only where the writes split.
#include <cstddef>
#include <cstdint>
#include <deque>
#include <limits>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "core/sim/faults.h"

namespace ydscope {

enum class DeliveryKind : std::uint8_t { Whole, Burst, Random };

struct DeliveryModel {
  DeliveryKind kind = DeliveryKind::Whole;
  std::uint32_t burst_bytes = 64;        // Burst: a full USB packet
  std::int64_t interval_ns = 1'000'000;  // Burst: the latency timer
  std::uint32_t max_piece = 32;          // Random: the largest write

  friend bool operator==(const DeliveryModel&, const DeliveryModel&) = default;
};

// "whole", "burst:BYTES:US" (e.g. burst:64:1000), "random:MAX" (e.g. random:17). On failure returns
// empty and, when error is given, says what is wrong in a sentence.
std::optional<DeliveryModel> parse_delivery(std::string_view text, std::string* error = nullptr);
// The text parse_delivery reads back.
std::string delivery_text(const DeliveryModel& model);

// Holds the bytes the line carried and releases them as separate writes per the model.
class DeliveryShaper {
 public:
  static constexpr std::int64_t kNever = std::numeric_limits<std::int64_t>::max();

  // baud paces Random's writes; seed makes Random's splits repeatable.
  DeliveryShaper(const DeliveryModel& model, std::uint32_t baud, std::uint64_t seed, std::int64_t now_ns);

  // Bytes whose last bit left the device's line by now_ns (non-decreasing).
  void push(std::int64_t now_ns, std::span<const std::uint8_t> bytes);
  // Appends the bytes due by now_ns to out; piece_ends gets the end offset (in out) of every
  // write the bridge makes, in order.
  void pop(std::int64_t now_ns, std::vector<std::uint8_t>& out, std::vector<std::size_t>& piece_ends);
  // When pop() will next have a piece; kNever when nothing is held.
  std::int64_t next_due_ns() const;
  // The bridge lost power (unplug): held bytes are gone.
  void clear();
  std::size_t held() const { return bytes_.size(); }
  const DeliveryModel& model() const { return model_; }

 private:
  std::size_t next_random_piece();
  std::int64_t random_due_ns() const;

  DeliveryModel model_;
  double ns_per_byte_;
  FaultRandom random_;
  std::deque<std::uint8_t> bytes_;
  std::deque<std::pair<std::int64_t, std::size_t>> arrivals_;  // (time, bytes) of what is held, oldest first
  std::int64_t next_tick_ns_;                                  // Burst: the next latency-timer tick
  std::int64_t line_free_ns_ = 0;  // Random: when the previous write would have finished on the line
  std::size_t piece_ = 0;          // Random: size of the next write (0 = not drawn yet)
};

}  // namespace ydscope
