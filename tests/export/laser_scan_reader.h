#pragma once
// What a test needs to know of a sensor_msgs/LaserScan as ydscope writes it
// (core/export/ros_encoding.h), read with the tests' own CDR reader.
#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

#include "export/cdr_test_reader.h"

namespace ydscope::test {

struct ScanSeen {
  std::uint64_t stamp_ns = 0;
  std::string frame_id;
  float time_increment = 0;
  float scan_time = 0;
  float range_min = 0;
  float range_max = 0;
  std::size_t bins = 0;
  std::size_t returns = 0;  // bins with a range
  std::vector<float> ranges;
  std::vector<float> intensities;
};

inline ScanSeen laser_scan(const std::vector<std::uint8_t>& cdr) {
  CdrReader r(cdr);
  ScanSeen scan;
  scan.stamp_ns = static_cast<std::uint64_t>(r.i32()) * 1'000'000'000u;
  scan.stamp_ns += r.u32();
  scan.frame_id = r.str();
  for (int i = 0; i < 3; ++i) r.f32();  // angle_min, angle_max, angle_increment
  scan.time_increment = r.f32();
  scan.scan_time = r.f32();
  scan.range_min = r.f32();
  scan.range_max = r.f32();
  scan.ranges = r.f32s();
  scan.intensities = r.f32s();
  scan.bins = scan.ranges.size();
  for (const float range : scan.ranges) scan.returns += std::isfinite(range) && range > 0 ? 1 : 0;
  return scan;
}

}  // namespace ydscope::test
