#pragma once
// What the Plots panel draws over time: per lap the measured against the set scan rate, the points
// in the lap and its latency to the screen; per second the bytes received and the checksum errors
// and CRC8 failures that arrived in that second; each sample with its time, and the events (stalls,
// reconnects, scan-rate and health changes) on the same time axis. Fed by the app, cleared with the
// session.
#include <array>
#include <cstdint>
#include <optional>

#include "ui/view/history/metric_history.h"
#include "ui/view/history/plot_events.h"

namespace ydscope::ui {

struct LapSample {
  double time_s = 0;                  // the app's seconds when the lap was measured
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
  std::uint64_t reconnects = 0;
};

// Whose health a change is: values of different sources are not compared with each other.
enum class HealthSource { CtBits, HealthAnswer, Count };

class RunPlots {
 public:
  static constexpr std::size_t kLaps = 1200;    // two minutes at 10 Hz, as long as the per-second plots
  static constexpr std::size_t kSeconds = 120;  // two minutes

  void add_lap(const LapSample& lap);
  // The first latency after a lap belongs to it (measured when the frame showing it is presented).
  void add_latency_ms(double ms, double time_s);
  // Marks a health change when `value` differs from the last one of `source` (the first is not a change).
  void note_health(HealthSource source, std::uint32_t value, double time_s);
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
  // Each series' sample times, advancing with it: rate_times() with measured_hz() and set_hz(),
  // lap_times() with points(), latency_times() with latency_ms(), second_times() with the rest.
  const MetricHistory& rate_times() const { return rate_times_; }
  const MetricHistory& lap_times() const { return lap_times_; }
  const MetricHistory& latency_times() const { return latency_times_; }
  const MetricHistory& second_times() const { return second_times_; }
  // A stall is marked once where the stream was interrupted (a run of cut laps is one stall), so
  // a gap in a line is not read as the motor slowing.
  const PlotEvents& events() const { return events_; }
  // How far back from `now_s` the oldest sample of any series goes (0 with none).
  double held_s(double now_s) const;

 private:
  MetricHistory measured_hz_{kLaps}, set_hz_{kLaps}, points_{kLaps}, latency_ms_{kLaps};
  MetricHistory rate_times_{kLaps}, lap_times_{kLaps}, latency_times_{kLaps};
  MetricHistory bytes_per_s_{kSeconds}, checksum_per_s_{kSeconds}, crc8_per_s_{kSeconds}, second_times_{kSeconds};
  std::optional<CounterSample> last_second_;
  PlotEvents events_;
  bool last_lap_interrupted_ = false;
  std::optional<double> last_set_hz_;
  std::array<std::optional<std::uint32_t>, static_cast<std::size_t>(HealthSource::Count)> last_health_{};
};

}  // namespace ydscope::ui
