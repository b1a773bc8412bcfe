#pragma once
// Statistics of the points that fall in a Sector, over one lap or many: how many, how many valid,
// the spread of their ranges, a histogram, and the valid share per angle bin (a dirty window or a
// weak spot shows up as a dip). The app feeds one lap at a time and clears; the CLI's check feeds
// a whole run.
#include <cstddef>
#include <cstdint>
#include <vector>

#include "core/analysis/sector.h"
#include "core/analysis/value_summary.h"
#include "core/protocol/lap.h"

namespace ydscope {

struct SectorStatisticsOptions {
  std::size_t histogram_bins = 40;
  std::size_t angle_bins = 20;
};

struct SectorStatistics {
  std::uint64_t laps = 0;
  std::uint64_t points = 0;  // points in the sector, with or without a return
  std::uint64_t valid = 0;   // of which valid returns (is_valid_return)
  double valid_share = 0;    // valid / points; 0 when there were no points
  ValueSummary range_mm;     // over the valid returns
  // Range projected on the sector's bisector (range * cos(angle - centre)): the distance to a flat
  // target square to the bisector, the same for every point on it. Bias and noise use this.
  ValueSummary flat_distance_mm;
  Histogram histogram;       // of range_mm, over its min..max
  double angle_bin_deg = 0;  // width of one angle bin
  // Valid share per angle bin from from_deg on; negative where a bin got no points at all.
  std::vector<double> valid_share_by_angle;
};

class SectorAccumulator {
 public:
  explicit SectorAccumulator(Sector sector, SectorStatisticsOptions options = {});

  void add(const Lap& lap);
  void clear();
  // Computed on demand (sorts copies for the medians); cheap enough once per lap.
  SectorStatistics statistics() const;
  const Sector& sector() const { return sector_; }

 private:
  Sector sector_;
  SectorStatisticsOptions options_;
  std::uint64_t laps_ = 0;
  std::uint64_t points_ = 0;
  std::vector<float> ranges_;
  std::vector<float> flat_distances_;
  std::vector<std::uint32_t> bin_points_;
  std::vector<std::uint32_t> bin_valid_;
};

}  // namespace ydscope
