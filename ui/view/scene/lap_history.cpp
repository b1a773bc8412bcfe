#include "ui/view/scene/lap_history.h"

#include <algorithm>
#include <atomic>
#include <stdexcept>

namespace ydscope::ui {
namespace {

std::atomic<std::uint64_t> laps_pushed{0};

}  // namespace

LapHistory::LapHistory(std::size_t depth) : slots_(kMaxDepth), depth_(std::clamp<std::size_t>(depth, 1, kMaxDepth)) {}

void LapHistory::set_depth(std::size_t depth) {
  depth_ = std::clamp<std::size_t>(depth, 1, kMaxDepth);
  count_ = std::min(count_, depth_);
  ++generation_;
}

void LapHistory::push(const Lap& lap) {
  HistoryLap& slot = slots_[next_];
  slot.serial = ++laps_pushed;
  slot.index = lap.index;
  slot.first_rx_ns = lap.first_rx_ns;
  slot.last_rx_ns = lap.last_rx_ns;
  slot.points.assign(lap.points.begin(), lap.points.end());  // reuses the slot's capacity
  next_ = (next_ + 1) % slots_.size();
  count_ = std::min(count_ + 1, depth_);
  ++generation_;
}

void LapHistory::clear() {
  count_ = 0;
  ++generation_;
}

const HistoryLap& LapHistory::at_age(std::size_t age) const {
  if (age >= count_) throw std::out_of_range("LapHistory::at_age beyond the laps held");
  const std::size_t n = slots_.size();
  return slots_[(next_ + n - 1 - age) % n];
}

std::size_t LapHistory::total_points() const {
  std::size_t total = 0;
  for (std::size_t age = 0; age < count_; ++age) total += at_age(age).points.size();
  return total;
}

}  // namespace ydscope::ui
