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
  std::string frame_id;
  float range_max = 0;
  std::size_t bins = 0;
  std::size_t returns = 0;  // bins with a range
};

inline ScanSeen laser_scan(const std::vector<std::uint8_t>& cdr) {
  CdrReader r(cdr);
  ScanSeen scan;
  r.i32();
  r.u32();
  scan.frame_id = r.str();
  for (int i = 0; i < 6; ++i) r.f32();  // angle_min, angle_max, increment, time_increment, scan_time, range_min
  scan.range_max = r.f32();
  const std::vector<float> ranges = r.f32s();
  scan.bins = ranges.size();
  for (const float range : ranges) scan.returns += std::isfinite(range) && range > 0 ? 1 : 0;
  return scan;
}

}  // namespace ydscope::test
