#pragma once
// ROS 2 messages in CDR, built from ydscope's laps and counters. /scan is binned the way the
// official ROS 2 driver (ydlidar_ros2_driver + YDLidar-SDK) bins, with REP-117's special values
// where the driver writes 0; /points keeps every return.
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
  // The robot's frame every lidar is placed in on /tf_static (REP-103; core/export/ros_tf.h).
  std::string parent_frame_id = "base_link";
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

// A LaserScan's times (REP-117): the header stamp is the first ray, time_increment lies between
// rays, scan_time is one turn. Taken from the lap's own receive times, so the first lap of a
// stream has them too.
struct ScanTimes {
  std::uint64_t stamp_ns = 0;   // the lap's first receive time, ns since the Unix epoch
  double scan_time_s = 0;       // first receive time to the closing byte's
  double time_increment_s = 0;  // scan_time_s over the lap's samples
};
// `rx_to_epoch_ns` turns the lap's receive times into ns since the Unix epoch. Count the samples
// before any interference filter: the filter removes rays, not the time between them.
ScanTimes scan_times(const Lap& lap, std::int64_t rx_to_epoch_ns);

// A lap point's range (mm) as /scan says it, in metres (REP-117): +Inf for no return (the
// unit's 0) and beyond range_max, -Inf below range_min (too close to measure), else the range.
float scan_range(float range_mm, RangeLimits limits);

// CDR of the messages; `out` is replaced (its capacity is reused from call to call).
// A bin no sample fell in is NaN (no measurement); `intensities` is empty, because no unit
// ydscope reads has a return strength in its samples (G1's flag bits are not one).
void encode_laser_scan(const Lap& lap, const RosFrameOptions& frame, RangeLimits limits, const ScanTimes& times,
                       std::vector<float>& scratch, std::vector<std::uint8_t>& out);
// PointCloud2, one row of the lap's returns: a sample without a return is left out, so the
// cloud holds no point at the origin and is_dense is true. Fields x y z float32 (m, ROS frame),
// range float32 (m), angle float32 (the corrected device angle in degrees, as decode prints it),
// and, with `interference_flag` (a unit that flags interference: G1's S & 3, 2 specular
// reflection, 3 ambient light), interference_flag uint8.
void encode_point_cloud(const Lap& lap, const RosFrameOptions& frame, bool interference_flag, std::uint64_t stamp_ns,
                        std::vector<std::uint8_t>& out);
inline constexpr std::uint32_t kPointStep = 24;             // with interference_flag (and padding)
inline constexpr std::uint32_t kPointStepWithoutFlag = 20;  // x y z range angle

struct DiagnosticReport {
  std::uint8_t level = 0;  // diagnostic_msgs/DiagnosticStatus: 0 OK, 1 WARN, 2 ERROR, 3 STALE
  std::string name;
  std::string message;
  std::string hardware_id;
  std::vector<std::pair<std::string, std::string>> values;
};
void encode_diagnostics(const DiagnosticReport& report, std::string_view frame_id, std::uint64_t stamp_ns,
                        std::vector<std::uint8_t>& out);
// Several statuses in one array (a lidar's and its zones').
void encode_diagnostics(std::span<const DiagnosticReport> reports, std::string_view frame_id, std::uint64_t stamp_ns,
                        std::vector<std::uint8_t>& out);

// std_msgs/UInt8MultiArray with an empty layout: the link bytes exactly.
void encode_link_bytes(std::span<const std::uint8_t> bytes, std::vector<std::uint8_t>& out);

}  // namespace ydscope
