#include "core/sim/delivery.h"

#include <algorithm>
#include <charconv>
#include <cmath>

namespace ydscope {

namespace {

constexpr std::uint64_t kRandomSalt = 0xDE11;  // its own generator: never moves a fault decision
constexpr std::uint32_t kMaxBurstBytes = 4096;
constexpr std::int64_t kMaxIntervalUs = 1'000'000;
constexpr std::uint32_t kMaxPiece = 4096;

bool parse_unsigned(std::string_view text, std::uint64_t& value) {
  const auto [ptr, ec] = std::from_chars(text.data(), text.data() + text.size(), value);
  return !text.empty() && ec == std::errc() && ptr == text.data() + text.size();
}

std::optional<DeliveryModel> fail(std::string* error, std::string message) {
  if (error) *error = std::move(message);
  return std::nullopt;
}

}  // namespace

std::optional<DeliveryModel> parse_delivery(std::string_view text, std::string* error) {
  DeliveryModel model;
  if (text == "whole") return model;
  std::uint64_t a = 0;
  std::uint64_t b = 0;
  if (text.starts_with("burst:")) {
    const std::string_view rest = text.substr(6);
    const auto colon = rest.find(':');
    if (colon == std::string_view::npos || !parse_unsigned(rest.substr(0, colon), a) ||
        !parse_unsigned(rest.substr(colon + 1), b) || a < 1 || a > kMaxBurstBytes || b < 1 ||
        b > static_cast<std::uint64_t>(kMaxIntervalUs))
      return fail(error,
                  "burst needs BYTES (1..4096) and an interval in microseconds (1..1000000), such as "
                  "burst:64:1000");
    model.kind = DeliveryKind::Burst;
    model.burst_bytes = static_cast<std::uint32_t>(a);
    model.interval_ns = static_cast<std::int64_t>(b) * 1000;
    return model;
  }
  if (text.starts_with("random:")) {
    if (!parse_unsigned(text.substr(7), a) || a < 1 || a > kMaxPiece)
      return fail(error, "random needs the largest write in bytes (1..4096), such as random:17");
    model.kind = DeliveryKind::Random;
    model.max_piece = static_cast<std::uint32_t>(a);
    return model;
  }
  return fail(error,
              "the delivery models are whole, burst:BYTES:US (e.g. burst:64:1000) and random:MAX (e.g. "
              "random:17)");
}

std::string delivery_text(const DeliveryModel& model) {
  switch (model.kind) {
    case DeliveryKind::Whole: return "whole";
    case DeliveryKind::Burst:
      return "burst:" + std::to_string(model.burst_bytes) + ":" + std::to_string(model.interval_ns / 1000);
    case DeliveryKind::Random: return "random:" + std::to_string(model.max_piece);
  }
  return "whole";
}

DeliveryShaper::DeliveryShaper(const DeliveryModel& model, std::uint32_t baud, std::uint64_t seed, std::int64_t now_ns)
    : model_(model),
      ns_per_byte_(10.0 * 1e9 / static_cast<double>(baud)),
      random_(seed ^ kRandomSalt),
      next_tick_ns_(now_ns + model.interval_ns) {}

std::size_t DeliveryShaper::next_random_piece() { return 1 + random_.below(model_.max_piece); }

std::int64_t DeliveryShaper::random_due_ns() const {
  // The next write goes once its n bytes are here and the line could have carried them since the
  // last write; when fewer are held, once the line has been quiet for as long.
  const std::size_t n = piece_;
  const auto line_time = [&](std::size_t bytes) {
    return static_cast<std::int64_t>(std::ceil(static_cast<double>(bytes) * ns_per_byte_));
  };
  if (bytes_.size() < n)
    return std::max(arrivals_.back().first + line_time(n), line_free_ns_ + line_time(bytes_.size()));
  std::int64_t nth_arrival = arrivals_.front().first;
  std::size_t seen = 0;
  for (const auto& [time, count] : arrivals_) {
    nth_arrival = time;
    seen += count;
    if (seen >= n) break;
  }
  return std::max(nth_arrival, line_free_ns_ + line_time(n));
}

void DeliveryShaper::push(std::int64_t now_ns, std::span<const std::uint8_t> bytes) {
  if (bytes.empty()) return;
  if (bytes_.empty() && model_.kind == DeliveryKind::Burst && next_tick_ns_ <= now_ns) {
    // Idle since: the timer keeps its phase, and the first tick that can carry these is the next.
    const std::int64_t behind = (now_ns - next_tick_ns_) / model_.interval_ns + 1;
    next_tick_ns_ += behind * model_.interval_ns;
  }
  bytes_.insert(bytes_.end(), bytes.begin(), bytes.end());
  arrivals_.emplace_back(now_ns, bytes.size());
  if (piece_ == 0) piece_ = next_random_piece();
}

void DeliveryShaper::pop(std::int64_t now_ns, std::vector<std::uint8_t>& out, std::vector<std::size_t>& piece_ends) {
  // Moves n held bytes to out as one write.
  const auto release = [&](std::size_t n) {
    out.insert(out.end(), bytes_.begin(), bytes_.begin() + static_cast<std::ptrdiff_t>(n));
    bytes_.erase(bytes_.begin(), bytes_.begin() + static_cast<std::ptrdiff_t>(n));
    piece_ends.push_back(out.size());
    for (std::size_t left = n; left > 0;) {
      auto& [t, count] = arrivals_.front();
      const std::size_t take = std::min(left, count);
      count -= take;
      left -= take;
      if (count == 0) arrivals_.pop_front();
    }
  };
  // Held bytes that had arrived by t.
  const auto arrived_by = [&](std::int64_t t) {
    std::size_t n = 0;
    for (const auto& [time, count] : arrivals_) {
      if (time > t) break;
      n += count;
    }
    return n;
  };

  switch (model_.kind) {
    case DeliveryKind::Whole:
      if (!bytes_.empty()) release(bytes_.size());
      break;
    case DeliveryKind::Burst:
      while (!bytes_.empty() && next_tick_ns_ <= now_ns) {
        const std::int64_t tick = next_tick_ns_;
        next_tick_ns_ += model_.interval_ns;
        std::size_t ready = arrived_by(tick);
        for (; ready >= model_.burst_bytes; ready -= model_.burst_bytes) release(model_.burst_bytes);
        // The latency timer: a partial packet goes once it has waited a whole interval.
        if (ready > 0 && arrivals_.front().first <= tick - model_.interval_ns) release(ready);
      }
      break;
    case DeliveryKind::Random:
      while (!bytes_.empty()) {
        const std::int64_t due = random_due_ns();
        if (due > now_ns) break;
        release(std::min(piece_, bytes_.size()));
        line_free_ns_ = due;
        piece_ = next_random_piece();
      }
      break;
  }
}

std::int64_t DeliveryShaper::next_due_ns() const {
  if (bytes_.empty()) return kNever;
  switch (model_.kind) {
    case DeliveryKind::Whole: return arrivals_.front().first;
    case DeliveryKind::Burst: return next_tick_ns_;
    case DeliveryKind::Random: return random_due_ns();
  }
  return kNever;
}

void DeliveryShaper::clear() {
  bytes_.clear();
  arrivals_.clear();
}

}  // namespace ydscope
