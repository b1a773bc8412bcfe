#include "core/analysis/lap_timing.h"

#include <algorithm>
#include <cmath>

#include "core/analysis/text_format.h"
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
// A lap lasting more than 1.5 median periods (beyond its turns) was not all heard, unless the laps
// after it make up for the time (a late read, see statistics()); they get this many laps to.
constexpr double kInterruptionPeriods = 1.5;
constexpr std::size_t kCatchUpLaps = 8;

}  // namespace

void LapTimingAccumulator::add(const Lap& lap) {
  // Close to close is the same event each time. The lap's own first byte to last byte is not (the
  // zero packet's first byte against the next one's last byte), so a lap without its predecessor
  // (the first, or one after laps the queue dropped) has no period of its own.
  const bool follows = have_previous_ && lap.index == previous_index_ + 1;
  LapRecord record{lap.index,
                   lap.last_rx_ns,
                   follows,
                   follows ? lap.last_rx_ns - previous_close_ns_ : 0,
                   static_cast<std::uint32_t>(lap.points.size()),
                   0,
                   0.0,
                   lap.end,
                   lap.longest_wait_ns > kStreamStallNs};
  have_previous_ = true;
  previous_index_ = lap.index;
  previous_close_ns_ = lap.last_rx_ns;
  raw_angles_.clear();
  for (const LapPoint& p : lap.points)
    raw_angles_.push_back(lap.angles_corrected && p.range_mm > 0.0f ? p.angle_deg - angle_correction_deg(p.range_mm)
                                                                    : p.angle_deg);
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
    // The next lap starts where this one did, so the tail up to there is part of this lap too;
    // a lap cut short ends where it was cut.
    if (lap.end == LapEnd::ZeroPacket) {
      double tail = step_between(raw_angles_.back(), raw_angles_.front());
      if (tail <= 0) tail += 360.0;
      steps_.push_back(tail);
      covered += tail;
    }
    for (const double d : steps_)
      if (d > kGapSteps * step) record.missing += static_cast<std::uint32_t>(std::lround(d / step) - 1);
    record.turns = covered / 360.0;
  }
  laps_.push_back(record);
}

namespace {

// Median of (t[i + h] - t[i]) / (count[i + h] - count[i]) with h half the laps: the time per lap
// over half-run baselines. Theil-Sen restricted to long pairs, so it stays linear in the laps.
double robust_seconds_per_lap(const std::vector<std::pair<double, double>>& count_and_time) {
  const std::size_t n = count_and_time.size();
  if (n < 2) return 0;
  const std::size_t h = std::max<std::size_t>(1, n / 2);
  std::vector<double> slopes;
  for (std::size_t i = 0; i + h < n; ++i) {
    const double laps = count_and_time[i + h].first - count_and_time[i].first;
    if (laps > 0) slopes.push_back((count_and_time[i + h].second - count_and_time[i].second) / laps);
  }
  return summarize_values(std::span<double>(slopes)).median;
}

}  // namespace

const char* timing_gap_cause(TimingGap::Cause cause) {
  return cause == TimingGap::Cause::Stall ? "the stream stalled" : "a zero packet was lost";
}

std::string describe_timing_gap(const TimingGap& gap) {
  std::string text =
      format_text("at %.1f s for %.1f s: %s", gap.from_s, gap.to_s - gap.from_s, timing_gap_cause(gap.cause));
  const long turns = std::lround(gap.turns_lost);
  if (turns > 0) text += format_text(" (about %ld turn%s unheard)", turns, turns == 1 ? "" : "s");
  return text;
}

std::vector<TimingGap> LapTimingAccumulator::gaps(const std::vector<double>& spans,
                                                  const std::vector<std::pair<double, double>>& count_and_time,
                                                  double median_period) const {
  std::vector<TimingGap> out;
  bool open = false;  // the last gap ended at a cut lap's close: the long lap after it continues it
  for (std::size_t i = 0; i < laps_.size(); ++i) {
    const LapRecord& r = laps_[i];
    const double close = count_and_time[i].second;
    if (spans[i] == 1.0) {
      open = false;
      continue;
    }
    if (r.end != LapEnd::ZeroPacket) {
      const auto cause = r.end == LapEnd::Stall ? TimingGap::Cause::Stall : TimingGap::Cause::LostZeroPacket;
      out.push_back({cause, close, close, 0.0});
      open = true;
      continue;
    }
    // A lap of more than one period: laps resumed one period before it closed.
    const double resumed = std::max(close - median_period, i ? count_and_time[i - 1].second : close);
    if (!open) {
      const auto cause = r.turns >= 1.5 && !r.stalled ? TimingGap::Cause::LostZeroPacket : TimingGap::Cause::Stall;
      out.push_back({cause, i ? count_and_time[i - 1].second : close, resumed, 0.0});
    }
    out.back().to_s = resumed;
    out.back().turns_lost += spans[i] - 1.0;
    open = false;
  }
  return out;
}

LapTimingStatistics LapTimingAccumulator::statistics() const {
  LapTimingStatistics s;
  s.laps = laps_.size();
  if (laps_.empty()) return s;
  std::vector<double> periods;
  for (const LapRecord& r : laps_)
    if (r.timed) periods.push_back(static_cast<double>(r.period_ns) * 1e-9);
  const double median_period = summarize_values(std::span<double>(periods)).median;
  // How many lap periods each lap lasted. The angle tells a lost lap start (two turns in one
  // lap). Time tells laps the lidar sent nothing for (a stall), but a host that read late sees
  // the same long gap, followed by laps closing in a burst as it catches up. So a gap counts as
  // silence only for the excess time the next few laps do not make up for.
  std::vector<double> turns(laps_.size()), excess(laps_.size(), 0.0);
  const auto cut = [this](std::size_t i) { return laps_[i].end != LapEnd::ZeroPacket; };
  for (std::size_t i = 0; i < laps_.size(); ++i) {
    turns[i] = cut(i) ? laps_[i].turns : std::max(1.0, std::round(laps_[i].turns));
    if (laps_[i].timed && median_period > 0)
      excess[i] = static_cast<double>(laps_[i].period_ns) * 1e-9 - median_period * turns[i];
  }
  std::vector<double> spans(laps_.size());
  for (std::size_t i = 0; i < laps_.size(); ++i) {
    if (cut(i)) {  // part of a turn, and an interruption whatever its time
      spans[i] = std::min(turns[i], 0.999);
      continue;
    }
    double silent = excess[i];
    double made_up = 0;
    for (std::size_t j = i + 1; j < laps_.size() && j <= i + kCatchUpLaps && laps_[j].timed; ++j) {
      made_up += excess[j];
      silent = std::min(silent, excess[i] + made_up);
    }
    const double silent_laps =
        silent > (kInterruptionPeriods - 1.0) * median_period ? std::round(silent / median_period) : 0.0;
    spans[i] = turns[i] + std::max(0.0, silent_laps);
  }

  std::vector<double> samples;                            // per normal lap
  std::vector<std::pair<double, double>> count_and_time;  // revolutions so far, close time (s)
  double revolutions = 0;
  const std::int64_t t0 = laps_.front().close_ns;
  for (std::size_t i = 0; i < laps_.size(); ++i) {
    const LapRecord& r = laps_[i];
    s.points += r.points;
    const double spanned = spans[i];
    // Laps the queue dropped turned too, and an interrupted lap turned `spanned` times.
    const double dropped = i ? static_cast<double>(r.index - laps_[i - 1].index - 1) : 0.0;
    revolutions += dropped + spanned;
    count_and_time.emplace_back(revolutions, static_cast<double>(r.close_ns - t0) * 1e-9);
    if (spanned != 1.0) {
      ++s.interruptions;
      continue;
    }
    s.lost_samples += r.missing;
    samples.push_back(r.points + r.missing);
  }
  s.normal_laps = samples.size();
  s.gaps = gaps(spans, count_and_time, median_period);
  const double seconds_per_lap = robust_seconds_per_lap(count_and_time);
  if (seconds_per_lap > 0) s.mean_hz = 1.0 / seconds_per_lap;
  if (!samples.empty()) {
    std::vector<double> scratch = samples;
    const ValueSummary n = summarize_values(std::span<double>(scratch));
    s.samples_per_lap = n.mean;
    s.sample_rate_hz = n.mean * s.mean_hz;
    s.min_hz = n.max > 0 ? s.sample_rate_hz / n.max : 0;
    s.max_hz = n.min > 0 ? s.sample_rate_hz / n.min : 0;
    s.jitter_pct = n.median > 0 ? 100.0 * robust_stddev(std::span<double>(scratch)) / n.median : 0;
    std::size_t k = 0;
    for (std::size_t i = 0; i < laps_.size(); ++i) {
      if (spans[i] != 1.0) continue;
      s.series.push_back({count_and_time[i].second, s.sample_rate_hz / samples[k++], laps_[i].points});
    }
  }
  // An interrupted lap should have held one normal lap's samples per period it spanned.
  for (std::size_t i = 0; i < laps_.size(); ++i) {
    const LapRecord& r = laps_[i];
    const double spanned = spans[i];
    if (spanned <= 1.0) continue;
    const double expected = spanned * s.samples_per_lap;
    const double short_by = std::max(0.0, expected - r.points);
    s.lost_samples += std::max<std::uint64_t>(r.missing, static_cast<std::uint64_t>(std::llround(short_by)));
  }
  return s;
}

}  // namespace ydscope
