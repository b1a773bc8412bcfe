#include "core/analysis/lap_timing.h"

#include <algorithm>
#include <cmath>

#include "core/analysis/value_summary.h"
#include "core/protocol/angle_correction.h"

namespace ydscope {

namespace {

// First-level angle difference b - a in (-180, 180]: consecutive samples are never half a turn apart.
double step_between(double a, double b) {
  double d = std::fmod(b - a, 360.0);
  if (d <= -180.0) d += 360.0;
  if (d > 180.0) d -= 360.0;
  return d;
}

// A gap is a step of more than 1.5 samples: quantisation of the packet end angles (1/64 degree)
// moves a step by far less than half a sample at any rate the lidars support.
constexpr double kGapSteps = 1.5;
// A lap lasting more than 1.5 median periods has lost at least one lap start.
constexpr double kInterruptionPeriods = 1.5;

}  // namespace

void LapTimingAccumulator::add(const Lap& lap) {
  // Close to close is the same event each time. The lap's own first byte to last byte is not (the
  // zero packet's first byte against the next one's last byte), so a lap without its predecessor
  // (the first, or one after laps the queue dropped) has no period: it counts for samples only.
  const bool follows = have_previous_ && lap.index == previous_index_ + 1;
  LapRecord record{lap.last_rx_ns, follows ? lap.last_rx_ns - previous_close_ns_ : 0,
                   static_cast<std::uint32_t>(lap.points.size()), 0, 0.0};
  have_previous_ = true;
  previous_index_ = lap.index;
  previous_close_ns_ = lap.last_rx_ns;
  raw_angles_.clear();
  for (const LapPoint& p : lap.points)
    raw_angles_.push_back(p.range_mm > 0.0f ? p.angle_deg - angle_correction_deg(p.range_mm) : p.angle_deg);
  steps_.clear();
  double covered = 0;
  for (std::size_t i = 1; i < raw_angles_.size(); ++i) {
    const double d = step_between(raw_angles_[i - 1], raw_angles_[i]);
    covered += d;
    if (d > 0) steps_.push_back(d);
  }
  if (!steps_.empty()) {
    // Reordering the steps is harmless: only their sizes matter below.
    const double step = summarize_values(std::span<double>(steps_)).median;
    // The next lap starts where this one did, so the tail up to there is part of this lap too.
    double tail = step_between(raw_angles_.back(), raw_angles_.front());
    if (tail <= 0) tail += 360.0;
    steps_.push_back(tail);
    covered += tail;
    for (const double d : steps_)
      if (d > kGapSteps * step) record.missing += static_cast<std::uint32_t>(std::lround(d / step) - 1);
    record.turns = covered / 360.0;
  }
  laps_.push_back(record);
}

LapTimingStatistics LapTimingAccumulator::statistics() const {
  LapTimingStatistics s;
  s.laps = laps_.size();
  if (laps_.empty()) return s;
  std::vector<double> periods;
  for (const LapRecord& r : laps_)
    if (r.period_ns > 0) periods.push_back(static_cast<double>(r.period_ns) * 1e-9);
  const double median = summarize_values(std::span<double>(periods)).median;
  s.median_period_s = median;
  // How many lap periods each lap lasted, by its time and by the angle it covered.
  const auto periods_spanned = [median](const LapRecord& r) {
    if (r.period_ns > 0 && median > 0) {
      const double by_time = static_cast<double>(r.period_ns) * 1e-9 / median;
      if (by_time > kInterruptionPeriods) return std::max(2.0, std::round(by_time));
    }
    return std::max(1.0, std::round(r.turns));
  };

  std::vector<double> normal;
  double samples = 0, seconds = 0;
  const std::int64_t t0 = laps_.front().close_ns;
  for (const LapRecord& r : laps_) {
    s.points += r.points;
    if (periods_spanned(r) != 1.0) {
      ++s.interruptions;
      continue;
    }
    s.lost_samples += r.missing;
    if (r.period_ns <= 0) continue;
    const double period = static_cast<double>(r.period_ns) * 1e-9;
    normal.push_back(period);
    samples += r.points + r.missing;
    seconds += period;
    s.series.push_back({static_cast<double>(r.close_ns - t0) * 1e-9, 1.0 / period, r.points});
  }
  s.normal_laps = normal.size();
  if (!normal.empty()) {
    s.samples_per_lap = samples / static_cast<double>(normal.size());
    s.sample_rate_hz = samples / seconds;
    const ValueSummary p = summarize_values(std::span<double>(normal));
    s.mean_hz = 1.0 / p.mean;
    s.min_hz = 1.0 / p.max;
    s.max_hz = 1.0 / p.min;
    s.period_stddev_pct = 100.0 * p.stddev / median;
    s.jitter_pct = 100.0 * robust_stddev(std::span<double>(normal)) / median;
  }
  // An interrupted lap should have held one normal lap's samples per period it spanned.
  for (const LapRecord& r : laps_) {
    const double spanned = periods_spanned(r);
    if (spanned <= 1.0) continue;
    const double expected = spanned * s.samples_per_lap;
    const double short_by = std::max(0.0, expected - r.points);
    s.lost_samples += std::max<std::uint64_t>(r.missing, static_cast<std::uint64_t>(std::llround(short_by)));
  }
  return s;
}

}  // namespace ydscope
