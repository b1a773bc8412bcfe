#include "ui/view/history/run_plots.h"

namespace ydscope::ui {

void RunPlots::add_lap(const LapSample& lap) {
  // Both rate lines advance together, so a lap's set and measured values sit at one x.
  if (lap.interrupted) rate_break_pending_ = true;
  if (lap.measured_hz) {
    measured_hz_.add(static_cast<float>(*lap.measured_hz));
    set_hz_.add(static_cast<float>(lap.set_hz.value_or(*lap.measured_hz)));
    rate_breaks_.add(rate_break_pending_ ? 1.0f : 0.0f);
    rate_break_pending_ = false;
  }
  points_.add(static_cast<float>(lap.points));
  lap_breaks_.add(lap.interrupted ? 1.0f : 0.0f);
}

void RunPlots::sample_counters(const CounterSample& sample) {
  if (!last_second_ || sample.checksum_errors < last_second_->checksum_errors ||
      sample.crc8_failures < last_second_->crc8_failures || sample.now_s < last_second_->now_s) {
    last_second_ = sample;  // the first sample, or the totals started again: a new baseline
    return;
  }
  if (sample.now_s - last_second_->now_s < 1.0) return;
  bytes_per_s_.add(static_cast<float>(sample.bytes_per_s));
  checksum_per_s_.add(static_cast<float>(sample.checksum_errors - last_second_->checksum_errors));
  crc8_per_s_.add(static_cast<float>(sample.crc8_failures - last_second_->crc8_failures));
  last_second_ = sample;
}

void RunPlots::clear() {
  for (MetricHistory* h : {&measured_hz_, &set_hz_, &points_, &latency_ms_, &lap_breaks_, &rate_breaks_, &bytes_per_s_,
                           &checksum_per_s_, &crc8_per_s_})
    h->clear();
  last_second_.reset();
  rate_break_pending_ = false;
}

}  // namespace ydscope::ui
