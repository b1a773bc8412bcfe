#pragma once
// The points of a sensor_msgs/PointCloud2 as ydscope writes it (core/export/ros_encoding.h: one
// row, point_step 24, x y z range angle as float32, then the flag byte), read with the tests'
// own CDR reader, so a test can compare an MCAP's /points with the laps it should hold.
#include <cstdint>
#include <cstring>
#include <stdexcept>
#include <string>
#include <vector>

#include "export/cdr_test_reader.h"
#include "export/mcap_test_reader.h"

namespace ydscope::test {

struct CloudPoint {
  float angle_deg = 0;
  float range_m = 0;
  std::uint8_t flag = 0;
  bool operator==(const CloudPoint&) const = default;
};

inline std::vector<CloudPoint> point_cloud_points(const std::vector<std::uint8_t>& cdr) {
  constexpr std::size_t kStep = 24;
  CdrReader r(cdr);
  r.i32();  // stamp
  r.u32();
  r.str();  // frame_id
  r.u32();  // height
  const std::uint32_t width = r.u32();
  const std::uint32_t fields = r.u32();
  for (std::uint32_t i = 0; i < fields; ++i) r.str(), r.u32(), r.u8(), r.u32();
  r.u8();  // is_bigendian
  if (r.u32() != kStep) throw std::runtime_error("point_step is not 24");
  r.u32();  // row_step
  if (r.u32() != width * kStep) throw std::runtime_error("data is not width * point_step bytes");
  const std::uint8_t* data = r.take(width * kStep);
  std::vector<CloudPoint> points(width);
  for (std::size_t i = 0; i < width; ++i) {
    std::memcpy(&points[i].range_m, data + i * kStep + 12, 4);
    std::memcpy(&points[i].angle_deg, data + i * kStep + 16, 4);
    points[i].flag = data[i * kStep + 20];
  }
  return points;
}

// The id of the channel on `topic`, or 0.
inline std::uint16_t channel_on(const McapContents& contents, const std::string& topic) {
  for (const auto& [id, channel] : contents.channels)
    if (channel.topic == topic) return id;
  return 0;
}

}  // namespace ydscope::test
