#pragma once
// The zones as diagnostic statuses: one per zone, WARN while its rule is raised (something in a
// zone that should be clear, nothing in one that should hold something), OK otherwise, with what
// is in it and since when. `serve` and the MCAP files carry them on /zones (diagnostic_msgs/msg/
// DiagnosticArray, so Foxglove's Diagnostics panel reads them) and beside the lidar's own status
// on /diagnostics.
#include <string>
#include <string_view>
#include <vector>

#include "core/analysis/zone_watch.h"
#include "core/export/ros_encoding.h"

namespace ydscope {

// `lidar`: the frame the zones are watched from (its name keys each status: "ydscope zone: door
// (laser)"); `hardware_id` as the lidar's status has it.
std::vector<DiagnosticReport> zone_reports(const ZoneWatch& watch, std::string_view lidar,
                                           const std::string& hardware_id);

}  // namespace ydscope
