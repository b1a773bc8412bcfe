#pragma once
// RunningScan: the running stream's part of a session, on the I/O thread. It turns the link's
// bytes into laps with a ScanDecoder and publishes each to the lap stream, keeps the decoder's
// totals in the session's counters, and keeps the watch a scan needs: when the power-down
// keep-alive (A5 60) is due, and how long the link has been quiet.
#include <chrono>
#include <cstdint>
#include <memory>
#include <optional>
#include <span>
#include <string>

#include "core/protocol/lap_end_forecast.h"
#include "core/protocol/model_profile.h"
#include "core/protocol/scan_decoder.h"
#include "core/protocol/stream_diagnosis.h"

namespace ydscope {

class LapStream;
class SessionCounters;

class RunningScan {
 public:
  RunningScan(LapStream& laps, SessionCounters& counters) : laps_(laps), counters_(counters) {}

  // A fresh decoder for `profile`, with the user's scale when one is set: a new device, or the
  // lap a stop cut short, which is no lap. Returns the scale in use (mm per count).
  double restart(const ModelProfile& profile, const UnitConventions& conventions);
  // The user's scale (empty: the model's). Applies from the next restart.
  void set_scale_override(std::optional<double> mm_per_count) { scale_override_ = mm_per_count; }
  std::optional<double> distance_scale() const;

  // Decodes `bytes` received at rx_ns; returns how many bytes can come before a lap could close.
  LapEndOutlook feed(std::span<const std::uint8_t> bytes, std::int64_t rx_ns);

  // The lidar (re)started scanning at now_ns: quiet time and keep-alives count from here.
  void scanning_from(std::int64_t now_ns) { scan_started_ns_ = last_keepalive_ns_ = now_ns; }
  // True once a keep-alive period has passed since the last one (which it then counts as sent).
  bool keepalive_due(std::int64_t now_ns);
  // How long no byte came while scanning, when that is longer than `timeout`.
  std::optional<std::int64_t> stalled_for(std::int64_t now_ns, std::chrono::milliseconds timeout) const;
  // Why the bytes since the last restart make no packets, in one sentence (StreamDiagnosis); empty
  // once a packet has verified or while too few bytes have come.
  std::optional<std::string> diagnosis(const ModelProfile& expected, std::uint32_t baud) const;

 private:
  LapStream& laps_;
  SessionCounters& counters_;
  std::unique_ptr<ScanDecoder> decoder_;
  StreamDiagnosis diagnosis_;  // fed only until the decoder's first packet: a healthy stream skips it
  std::optional<double> scale_override_;
  std::int64_t scan_started_ns_ = 0;
  std::int64_t last_keepalive_ns_ = 0;
};

}  // namespace ydscope
