#pragma once
// Laps of the virtual lidar on a simulated clock, decoded as the host would: no threads, no pty,
// no wall-clock time, so the timing the analysis sees is exactly the device's (paced by its baud).
#include <cstdint>
#include <functional>
#include <vector>

#include "core/protocol/scan_decoder.h"
#include "core/sim/virtual_lidar.h"

namespace ydscope::test {

inline constexpr std::int64_t kMs = 1'000'000;

struct VirtualRun {
  std::vector<Lap> laps;
  std::vector<TruthPacket> truth;  // every packet generated, in order
  DecoderCounters decoder;
  FaultCounters faults;
  double distance_scale = 0;  // mm per count the lidar wrote with
};

// Starts the scan at t = 0 and collects `seconds` of laps, reading the line every millisecond.
inline VirtualRun scan_virtual_lidar(Model model, double seconds, const FaultConfig& faults = {},
                                     const std::string& scene = "room",
                                     const std::function<void(VirtualLidar&, std::int64_t&)>& before_scan = {}) {
  VirtualLidarConfig config;
  config.model = model;
  config.scene = scene;
  config.faults = faults;
  VirtualLidar lidar(config, 0);
  VirtualRun run;
  lidar.set_truth([&run](const TruthPacket& p) { run.truth.push_back(p); });
  std::int64_t now = 0;
  if (before_scan) before_scan(lidar, now);
  const std::uint8_t scan[] = {0xA5, 0x60};
  lidar.receive(scan, now);
  ScanDecoder decoder(lidar.profile(), lidar.conventions(), lidar.distance_scale());
  run.distance_scale = lidar.distance_scale();
  std::vector<std::uint8_t> bytes;
  const auto end = now + static_cast<std::int64_t>(seconds * 1e9);
  while (now < end) {
    now += kMs;
    bytes.clear();
    lidar.produce(now, bytes);
    decoder.feed(bytes, now, [&run](const Lap& lap) { run.laps.push_back(lap); });
  }
  run.decoder = decoder.counters();
  run.faults = lidar.fault_counters();
  return run;
}

}  // namespace ydscope::test
