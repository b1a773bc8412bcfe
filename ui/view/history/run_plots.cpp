#include "ui/view/history/run_plots.h"

#include <algorithm>
#include <cmath>

namespace ydscope::ui {

void RunPlots::add_lap(const LapSample& lap) {
  const auto t = static_cast<float>(lap.time_s);
  // The first lap of a session starts mid-turn: cut short, but no stall.
  if (lap.interrupted && !last_lap_interrupted_ && lap_times_.size() > 0) events_.add(PlotEventKind::Stall, lap.time_s);
  last_lap_interrupted_ = lap.interrupted;
  if (lap.set_hz) {
    if (last_set_hz_ && std::abs(*lap.set_hz - *last_set_hz_) > 1e-3)
      events_.add(PlotEventKind::RateChange, lap.time_s);
    last_set_hz_ = lap.set_hz;
  }
  // Both rate lines advance together, so a lap's set and measured values sit at one time.
  if (lap.measured_hz) {
    measured_hz_.add(static_cast<float>(*lap.measured_hz));
    set_hz_.add(static_cast<float>(lap.set_hz.value_or(*lap.measured_hz)));
    rate_times_.add(t);
  }
  points_.add(static_cast<float>(lap.points));
  lap_times_.add(t);
}

void RunPlots::add_latency_ms(double ms, double time_s) {
  latency_ms_.add(static_cast<float>(ms));
  latency_times_.add(static_cast<float>(time_s));
}

void RunPlots::note_health(HealthSource source, std::uint32_t value, double time_s) {
  std::optional<std::uint32_t>& last = last_health_[static_cast<std::size_t>(source)];
  if (last && *last != value) events_.add(PlotEventKind::HealthChange, time_s);
  last = value;
}

void RunPlots::sample_counters(const CounterSample& sample) {
  if (last_second_ && sample.reconnects > last_second_->reconnects) events_.add(PlotEventKind::Reconnect, sample.now_s);
  if (!last_second_ || sample.checksum_errors < last_second_->checksum_errors ||
      sample.crc8_failures < last_second_->crc8_failures || sample.now_s < last_second_->now_s) {
    last_second_ = sample;  // the first sample, or the totals started again: a new baseline
    return;
  }
  if (sample.reconnects > last_second_->reconnects) last_second_->reconnects = sample.reconnects;
  if (sample.now_s - last_second_->now_s < 1.0) return;
  bytes_per_s_.add(static_cast<float>(sample.bytes_per_s));
  checksum_per_s_.add(static_cast<float>(sample.checksum_errors - last_second_->checksum_errors));
  crc8_per_s_.add(static_cast<float>(sample.crc8_failures - last_second_->crc8_failures));
  second_times_.add(static_cast<float>(sample.now_s));
  last_second_ = sample;
}

double RunPlots::held_s(double now_s) const {
  double oldest = now_s;
  for (const MetricHistory* times : {&rate_times_, &lap_times_, &latency_times_, &second_times_})
    if (times->size() > 0) oldest = std::min(oldest, static_cast<double>(times->at(0)));
  return now_s - oldest;
}

void RunPlots::clear() {
  for (MetricHistory* h : {&measured_hz_, &set_hz_, &points_, &latency_ms_, &rate_times_, &lap_times_, &latency_times_,
                           &bytes_per_s_, &checksum_per_s_, &crc8_per_s_, &second_times_})
    h->clear();
  last_second_.reset();
  events_.clear();
  last_lap_interrupted_ = false;
  last_set_hz_.reset();
  last_health_ = {};
}

}  // namespace ydscope::ui
