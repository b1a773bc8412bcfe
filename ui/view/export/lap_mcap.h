#pragma once
// What the View panel's MCAP export writes: the laps on screen (frozen or live), never a newer
// lap the view has not shown, oldest first, as /scan (sensor_msgs/LaserScan) and /points
// (sensor_msgs/PointCloud2) in the same schemas `ydscope-cli export --mcap` uses, so Foxglove and
// `ros2 bag` open it. Each lap is logged at the wall-clock time its closing byte arrived and
// stamped at its first byte's, as the recorded topics are (McapRecordingExport::lap).
#include <cstddef>
#include <cstdint>
#include <string>

#include "core/protocol/model_profile.h"
#include "core/record/recording_metadata.h"
#include "ui/view/scene/lap_history.h"

namespace ydscope::ui {

struct ShownLapsMcap {
  std::size_t laps = 0;
  std::uint64_t messages = 0;
  std::string error;  // empty, or why the file could not be written
};

// The newest `laps` of `history` (all it holds when it holds fewer) into a new MCAP file at
// `path`. `model` gives /scan's range limits; `metadata` (the device, the port) goes in the file's
// "ydscope.recording" metadata; `rx_to_wall_ns` turns the laps' steady receive times into ns
// since the Unix epoch.
ShownLapsMcap save_shown_laps_mcap(const LapHistory& history, std::size_t laps, Model model,
                                   const RecordingMetadata& metadata, std::int64_t rx_to_wall_ns,
                                   const std::string& path);

}  // namespace ydscope::ui
