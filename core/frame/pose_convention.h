#pragma once
// Poses written before ydscope adopted REP-103 (settings.ini without `pose_convention`, recordings
// whose metadata has a pose but no `pose_convention`) meant x to the right, y forward, and a lidar
// at "0,0,0" facing forward with its 0 degrees. They are converted on load, so every old file
// still puts each lidar where it was, and the caller says so once.
#include <string_view>

#include "core/frame/pose.h"

namespace ydscope {

// The marker written beside every pose now (`pose_convention=rep103`).
inline constexpr std::string_view kPoseConventionKey = "pose_convention";
inline constexpr std::string_view kPoseConvention = "rep103";

// The same mount in REP-103 terms: (x, y) becomes (y, -x), and yaw turns by 180 degrees (the laser
// frame's forward is the unit's 180), kept within (-180, 180]; the upside-down mount stays.
Pose pose_from_pre_rep103(const Pose& old);

// The one sentence a caller gives when it converted.
inline constexpr std::string_view kPreRep103Note =
    "poses written before REP-103 (x right, y forward) were converted to REP-103 (x forward, y left, yaw "
    "counter-clockwise); they are saved that way from now on";

}  // namespace ydscope
