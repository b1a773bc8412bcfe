#pragma once
// The points of a sensor_msgs/PointCloud2 as ydscope writes it (core/export/ros_encoding.h: one
// row of the lap's returns, x y z range angle as float32, then the interference_flag byte where
// the unit has one), read with the tests' own CDR reader by the fields the message names, so a
// test can compare an MCAP's /points with the laps it should hold.
#include <cstdint>
#include <cstring>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "core/protocol/lap.h"
#include "export/cdr_test_reader.h"
#include "export/mcap_test_reader.h"

namespace ydscope::test {

struct CloudPoint {
  float angle_deg = 0;
  float range_m = 0;
  std::uint8_t flag = 0;  // interference_flag; 0 where the cloud has no such field
  bool operator==(const CloudPoint&) const = default;
};

struct CloudSeen {
  std::uint64_t stamp_ns = 0;
  std::vector<std::string> fields;
  std::uint32_t point_step = 0;
  bool is_dense = false;
  std::vector<CloudPoint> points;
};

inline CloudSeen point_cloud(const std::vector<std::uint8_t>& cdr) {
  CdrReader r(cdr);
  CloudSeen cloud;
  cloud.stamp_ns = static_cast<std::uint64_t>(r.i32()) * 1'000'000'000u;
  cloud.stamp_ns += r.u32();
  r.str();  // frame_id
  if (r.u32() != 1) throw std::runtime_error("height is not 1");
  const std::uint32_t width = r.u32();
  const std::uint32_t fields = r.u32();
  std::optional<std::uint32_t> range_at, angle_at, flag_at;
  for (std::uint32_t i = 0; i < fields; ++i) {
    const std::string name = r.str();
    const std::uint32_t offset = r.u32();
    r.u8();
    r.u32();
    cloud.fields.push_back(name);
    if (name == "range") range_at = offset;
    if (name == "angle") angle_at = offset;
    if (name == "interference_flag") flag_at = offset;
  }
  if (!range_at || !angle_at) throw std::runtime_error("no range or angle field");
  r.u8();  // is_bigendian
  cloud.point_step = r.u32();
  const std::uint32_t step = cloud.point_step;
  r.u32();  // row_step
  if (r.u32() != width * step) throw std::runtime_error("data is not width * point_step bytes");
  const std::uint8_t* data = r.take(width * step);
  cloud.is_dense = r.u8() != 0;
  cloud.points.resize(width);
  for (std::size_t i = 0; i < width; ++i) {
    std::memcpy(&cloud.points[i].range_m, data + i * step + *range_at, 4);
    std::memcpy(&cloud.points[i].angle_deg, data + i * step + *angle_at, 4);
    if (flag_at) cloud.points[i].flag = data[i * step + *flag_at];
  }
  return cloud;
}

inline std::vector<CloudPoint> point_cloud_points(const std::vector<std::uint8_t>& cdr) {
  return point_cloud(cdr).points;
}

// The points of a lap /points carries: its returns (a sample without one is left out).
inline std::vector<LapPoint> returns_of(const std::vector<LapPoint>& points) {
  std::vector<LapPoint> returns;
  for (const LapPoint& p : points)
    if (p.range_mm != 0.0f) returns.push_back(p);
  return returns;
}

// The id of the channel on `topic`, or 0.
inline std::uint16_t channel_on(const McapContents& contents, const std::string& topic) {
  for (const auto& [id, channel] : contents.channels)
    if (channel.topic == topic) return id;
  return 0;
}

}  // namespace ydscope::test
