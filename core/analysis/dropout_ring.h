#pragma once
// Blockage and dropouts: per degree of the turn, the share of samples that came back with no
// return over the last seconds, and the sectors that stayed empty while the rest of the turn saw
// returns (a bracket, a cable or dirt in front of the window). The app draws the ring and says the
// sectors, /diagnostics warns with them, and `check` fails on them.
//
// Samples are binned by where the window pointed (the first-level angle): a return's corrected
// angle is taken back by its correction, so a blocked sector's edges are where the obstruction is,
// not shifted by the triangulation correction of the returns beside it.
#include <array>
#include <cstdint>
#include <deque>
#include <string>
#include <vector>

#include "core/protocol/lap.h"

namespace ydscope {

inline constexpr std::size_t kDropoutBins = 360;  // one degree each

struct DropoutOptions {
  std::int64_t window_ns = 3'000'000'000;  // the share is over the laps of the last 3 s
  // Judged only once the laps held span this much, so one lap's gap is not called a blockage.
  std::int64_t min_span_ns = 1'000'000'000;
  double blocked_share = 0.95;  // a degree at least this empty is part of a blocked sector
  double min_width_deg = 4.0;   // narrower runs are edges and thin posts, not a blockage
  // The rest of the turn must see at least this share of returns: a lidar that sees nothing
  // anywhere (pointed at open sky) is not blocked in one place.
  double min_others_return_share = 0.2;
};

struct BlockedSector {
  int from_deg = 0;  // clockwise from..to, whole degrees; may cross 0 (to < from)
  int to_deg = 0;
  double for_s = 0.0;  // since the sector's last return (or since the first lap, if none came)

  int width_deg() const;
  double centre_deg() const;
};

// "blocked 40°–75° for 12 s".
std::string describe_blocked_sector(const BlockedSector& sector);
// Every sector's description, joined with "; ".
std::string describe_blocked_sectors(const std::vector<BlockedSector>& sectors);

class DropoutRing {
 public:
  explicit DropoutRing(DropoutOptions options = {});

  // The lap's time is its last_rx_ns; laps older than the window behind it are let go.
  void add_lap(const Lap& lap);
  void clear();

  // Share of no-return samples per degree over the window, 0..1; negative where no sample fell.
  std::array<float, kDropoutBins> no_return_share() const;
  // The blocked sectors as of the newest lap, clockwise from the one nearest 0°.
  std::vector<BlockedSector> blocked() const;
  bool empty() const { return laps_.empty(); }
  const DropoutOptions& options() const { return options_; }

 private:
  struct LapBins {
    std::int64_t t_ns = 0;
    std::array<std::uint16_t, kDropoutBins> samples{};
    std::array<std::uint16_t, kDropoutBins> misses{};
  };

  DropoutOptions options_;
  std::deque<LapBins> laps_;
  std::array<std::uint32_t, kDropoutBins> samples_{};  // totals over laps_
  std::array<std::uint32_t, kDropoutBins> misses_{};
  std::array<std::int64_t, kDropoutBins> last_return_ns_{};  // 0: none since the first lap
  std::int64_t first_ns_ = 0;
};

}  // namespace ydscope
