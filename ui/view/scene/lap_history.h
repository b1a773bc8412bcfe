#pragma once
// The last N laps kept for persistence: a ring of preallocated point buffers, so pushing a lap per
// frame allocates nothing once the ring is warm.
#include <cstddef>
#include <cstdint>
#include <vector>

#include "core/protocol/lap.h"

namespace ydscope::ui {

struct HistoryLap {
  // This push's own number, unique in the process: a cloud built from the lap is known by it
  // (a lap's index starts over when its source does).
  std::uint64_t serial = 0;
  std::uint64_t index = 0;
  std::int64_t first_rx_ns = 0;  // receive time of the lap's first byte
  std::int64_t last_rx_ns = 0;
  std::vector<LapPoint> points;
};

class LapHistory {
 public:
  static constexpr std::size_t kMaxDepth = 60;

  explicit LapHistory(std::size_t depth = 10);

  // How many laps are drawn (1 = only the newest). Keeps the newest laps when shrinking.
  void set_depth(std::size_t depth);
  std::size_t depth() const { return depth_; }

  void push(const Lap& lap);
  void clear();

  std::size_t size() const { return count_; }
  bool empty() const { return count_ == 0; }
  // age 0 is the newest lap; age < size().
  const HistoryLap& at_age(std::size_t age) const;
  const HistoryLap& newest() const { return at_age(0); }
  std::size_t total_points() const;
  // Changes whenever what it holds changes (a lap pushed, cleared, the depth set), so a cloud built
  // from it knows when to be built again.
  std::uint64_t generation() const { return generation_; }

 private:
  std::vector<HistoryLap> slots_;  // kMaxDepth slots; only the newest depth_ are visible
  std::size_t depth_;
  std::size_t next_ = 0;   // slot the next push writes
  std::size_t count_ = 0;  // laps held, <= depth_
  std::uint64_t generation_ = 0;
};

}  // namespace ydscope::ui
