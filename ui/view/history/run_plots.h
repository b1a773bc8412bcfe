#pragma once
// What the Plots panel draws over time: per lap the measured against the set scan rate, the points
// in the lap and its latency to the screen; per second the bytes received and the checksum errors
// and CRC8 failures that arrived in that second. Fed by the app, cleared with the session.
#include <cstdint>
#include <optional>

#include "ui/view/history/metric_history.h"

namespace ydscope::ui {

struct LapSample {
  std::optional<double> measured_hz;  // ScanRateMeter's, once it has enough laps
  std::optional<double> set_hz;       // the device's set value (A5 0D), when known
  std::size_t points = 0;
  bool interrupted = false;  // cut short or held up by a stall (Lap::whole() false)
};

// The session's running totals, sampled about once a frame.
struct CounterSample {
  double now_s = 0;
  double bytes_per_s = 0;
  std::uint64_t checksum_errors = 0;
  std::uint64_t crc8_failures = 0;
};

class RunPlots {
 public:
  static constexpr std::size_t kLaps = 300;     // half a minute at 10 Hz
  static constexpr std::size_t kSeconds = 120;  // two minutes

  void add_lap(const LapSample& lap);
  // The first latency after a lap belongs to it (measured when the frame showing it is presented).
  void add_latency_ms(double ms) { latency_ms_.add(static_cast<float>(ms)); }
  // Adds one per-second point whenever a second has passed since the last one.
  void sample_counters(const CounterSample& sample);
  void clear();

  const MetricHistory& measured_hz() const { return measured_hz_; }
  const MetricHistory& set_hz() const { return set_hz_; }
  const MetricHistory& points() const { return points_; }
  const MetricHistory& latency_ms() const { return latency_ms_; }
  const MetricHistory& bytes_per_s() const { return bytes_per_s_; }
  const MetricHistory& checksum_errors_per_s() const { return checksum_per_s_; }
  const MetricHistory& crc8_failures_per_s() const { return crc8_per_s_; }
  // 1 where the stream was interrupted, 0 elsewhere: per_lap_breaks() beside points(), and
  // rate_breaks() beside measured_hz() (the first rate measured after an interruption), so the
  // panel marks the gap instead of drawing straight across it.
  const MetricHistory& per_lap_breaks() const { return lap_breaks_; }
  const MetricHistory& rate_breaks() const { return rate_breaks_; }

 private:
  MetricHistory measured_hz_{kLaps}, set_hz_{kLaps}, points_{kLaps}, latency_ms_{kLaps};
  MetricHistory lap_breaks_{kLaps}, rate_breaks_{kLaps};
  bool rate_break_pending_ = false;
  MetricHistory bytes_per_s_{kSeconds}, checksum_per_s_{kSeconds}, crc8_per_s_{kSeconds};
  std::optional<CounterSample> last_second_;
};

}  // namespace ydscope::ui
