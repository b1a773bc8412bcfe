#pragma once
// How regularly the laps come and how many samples they should have held: the measured scan rate
// and its lap-to-lap variation, the sample rate, and an estimate of samples lost on the way.
//
// Host timing is the weak spot: a read that wakes late on a busy machine moves one lap's close by
// tens of milliseconds. So:
// - the scan rate is the slope of lap-close times against lap count, the median of the slopes
//   over half-run baselines: one late read moves few of them, and none by much;
// - the jitter comes from the lidar itself: its sample clock (the ranging frequency) is steady,
//   so the samples a lap holds measure how fast the motor turned in that lap. It is the robust
//   std-dev (robust_stddev) of the samples per lap, in % of their median;
// - a lap lasting more than 1.5 periods (its closing zero packet was lost, or the stream stalled)
//   is an interruption: left out of the per-lap figures, its missing samples counted instead; so
//   is a lap the decoder cut short (Lap::end), which covers only the part of a turn it holds.
//
// Missing samples are found from the angles: undoing the distance-only second-level correction
// gives each point's first-level angle, which the lidar spaces evenly, so a gap of k steps means
// k - 1 samples never arrived (a lost packet, one dropped for a bad checksum, a stall).
#include <cstddef>
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include "core/protocol/lap.h"

namespace ydscope {

struct LapRateSample {
  double t_s = 0;            // lap close, seconds after the first lap's close (host clock)
  double hz = 0;             // that lap's rate: sample rate / its samples
  std::uint32_t points = 0;  // received
};

// Where the laps stopped telling the motor's time, for the report to name and the plots to draw.
struct TimingGap {
  enum class Cause { Stall, LostZeroPacket };
  Cause cause = Cause::Stall;
  double from_s = 0;      // the last lap close before it (the series' clock)
  double to_s = 0;        // when laps resumed
  double turns_lost = 0;  // revolutions no lap covers
};

// "the stream stalled", "a zero packet was lost".
const char* timing_gap_cause(TimingGap::Cause cause);
// "at 3.2 s for 0.4 s: the stream stalled (about 3 turns unheard)", for every report format.
std::string describe_timing_gap(const TimingGap& gap);

struct LapTimingStatistics {
  std::uint64_t laps = 0;           // laps added
  std::uint64_t normal_laps = 0;    // laps of one period, used for the per-lap figures
  std::uint64_t interruptions = 0;  // laps spanning more than one period
  double mean_hz = 0;               // robust slope of the lap-close times
  double min_hz = 0;                // per-lap rates of the normal laps
  double max_hz = 0;
  double jitter_pct = 0;              // robust std-dev of samples per lap, % of their median
  double samples_per_lap = 0;         // mean of received + missing samples over the normal laps
  double sample_rate_hz = 0;          // samples_per_lap * mean_hz
  std::uint64_t points = 0;           // points received in all laps
  std::uint64_t lost_samples = 0;     // estimated samples missing from the laps (lost, or dropped with a cut lap)
  std::vector<LapRateSample> series;  // one entry per normal lap, in order
  std::vector<TimingGap> gaps;        // one per interruption (one or more laps), in order
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
    std::uint64_t index;  // Lap::index: laps the queue dropped leave a gap
    std::int64_t close_ns;
    bool timed;              // the previous lap was seen, so period_ns means something
    std::int64_t period_ns;  // from the previous lap's close; 0 when both closed in one read
    std::uint32_t points;
    std::uint32_t missing;  // from gaps in the first-level angles
    double turns;           // first-level angle covered, in turns (2 when a zero packet was lost)
    LapEnd end;             // a lap cut short covers part of a turn (and no tail back to its start)
    bool stalled;           // it waited longer than a stall inside
  };
  std::vector<TimingGap> gaps(const std::vector<double>& spans,
                              const std::vector<std::pair<double, double>>& count_and_time, double median_period) const;

  std::vector<LapRecord> laps_;
  bool have_previous_ = false;
  std::uint64_t previous_index_ = 0;
  std::int64_t previous_close_ns_ = 0;
  std::vector<double> raw_angles_;  // scratch, kept to avoid allocating per lap
  std::vector<double> steps_;
};

}  // namespace ydscope
