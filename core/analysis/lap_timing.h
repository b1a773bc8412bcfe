#pragma once
// How regularly the laps come and how many samples they should have held: the measured scan rate
// and its lap-to-lap jitter, the sample rate, and an estimate of samples lost on the way.
//
// The period of a lap is the time between the closing of the lap before it and its own closing, as
// the host received them (Lap::last_rx_ns): the same event each time, so byte timing cancels. A lap that spans several periods (its
// closing zero packet was lost, or the stream stalled) is an interruption: it is left out of the
// rate statistics and its missing samples are counted instead.
//
// Missing samples are found from the angles: undoing the distance-only second-level correction
// gives each point's first-level angle, which the lidar spaces evenly, so a gap of k steps means
// k - 1 samples never arrived (a lost packet, one dropped for a bad checksum, a stall).
#include <cstddef>
#include <cstdint>
#include <vector>

#include "core/protocol/lap.h"

namespace ydscope {

struct LapRateSample {
  double t_s = 0;       // lap close, seconds after the first lap's close
  double hz = 0;        // 1 / that lap's period
  std::uint32_t points = 0;
};

struct LapTimingStatistics {
  std::uint64_t laps = 0;           // laps added
  std::uint64_t normal_laps = 0;    // laps of one known period, used for the rate statistics
  std::uint64_t interruptions = 0;  // laps spanning more than one period
  double mean_hz = 0;               // 1 / mean period of the normal laps
  double min_hz = 0;
  double max_hz = 0;
  double median_period_s = 0;
  double jitter_pct = 0;            // robust std-dev of the period (see robust_stddev), % of the median
  double period_stddev_pct = 0;     // plain std-dev, % of the median (for the record; outliers count)
  double samples_per_lap = 0;       // mean of received + missing samples over the normal laps
  double sample_rate_hz = 0;        // samples (received + missing) / time, normal laps
  std::uint64_t points = 0;         // points received in all laps
  std::uint64_t lost_samples = 0;   // estimated samples that never arrived
  std::vector<LapRateSample> series;  // one entry per normal lap, in order
};

class LapTimingAccumulator {
 public:
  void add(const Lap& lap);
  void clear() {
    laps_.clear();
    have_previous_ = false;
  }
  LapTimingStatistics statistics() const;

 private:
  struct LapRecord {
    std::int64_t close_ns;
    std::int64_t period_ns;
    std::uint32_t points;
    std::uint32_t missing;  // from gaps in the first-level angles
    double turns;           // first-level angle covered, in turns (2 when a zero packet was lost)
  };
  std::vector<LapRecord> laps_;
  bool have_previous_ = false;
  std::uint64_t previous_index_ = 0;
  std::int64_t previous_close_ns_ = 0;
  std::vector<double> raw_angles_;  // scratch, kept to avoid allocating per lap
  std::vector<double> steps_;
};

}  // namespace ydscope
