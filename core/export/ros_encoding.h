#pragma once
// ROS 2 messages in CDR, built from ydscope's laps and counters. /scan is binned the way the
// official ROS 2 driver (ydlidar_ros2_driver + YDLidar-SDK) bins; /points keeps every point.
#include <cstdint>
#include <span>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "core/protocol/lap.h"
#include "core/protocol/model_profile.h"

namespace ydscope {

struct RosFrameOptions {
  std::string frame_id = "laser";
  // The official driver's `reversion` (+180 degrees) and `inverted` (counter-clockwise, as ROS
  // angles run); its G1, G6 and TG parameter files set both, and so do we by default.
  bool reversion = true;
  bool inverted = true;
};

// range_min / range_max of /scan in metres, per model (the official driver's parameter files
// for G1 and G6; the TG15/30/50 datasheets' ranges).
struct RangeLimits {
  float min_m;
  float max_m;
};
RangeLimits range_limits(Model model);

// A lap point's angle in the ROS frame, radians in (-pi, pi], as the SDK computes it.
double ros_angle_rad(float device_angle_deg, const RosFrameOptions& frame);

// CDR of the messages; `out` is replaced (its capacity is reused from call to call).
// stamp_ns: header stamp, ns since the Unix epoch. scan_time_s: time from the previous lap's
// close to this one's (0 when unknown).
void encode_laser_scan(const Lap& lap, const RosFrameOptions& frame, RangeLimits limits, std::uint64_t stamp_ns,
                       double scan_time_s, std::vector<float>& scratch, std::vector<std::uint8_t>& out);
// PointCloud2, one row, point_step 24: x y z float32 (m, ROS frame), range float32 (m),
// angle float32 (the corrected device angle in degrees, as decode prints it), flag uint8 (G1 S&3).
void encode_point_cloud(const Lap& lap, const RosFrameOptions& frame, std::uint64_t stamp_ns,
                        std::vector<std::uint8_t>& out);
inline constexpr std::uint32_t kPointStep = 24;

struct DiagnosticReport {
  std::uint8_t level = 0;  // diagnostic_msgs/DiagnosticStatus: 0 OK, 1 WARN, 2 ERROR, 3 STALE
  std::string name;
  std::string message;
  std::string hardware_id;
  std::vector<std::pair<std::string, std::string>> values;
};
void encode_diagnostics(const DiagnosticReport& report, std::string_view frame_id, std::uint64_t stamp_ns,
                        std::vector<std::uint8_t>& out);

// std_msgs/UInt8MultiArray with an empty layout: the link bytes exactly.
void encode_link_bytes(std::span<const std::uint8_t> bytes, std::vector<std::uint8_t>& out);

}  // namespace ydscope
