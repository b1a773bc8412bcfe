#pragma once
// SourceInfo: what one lidar of a set is, wherever a set of lidars goes (recordings, MCAP files,
// the Foxglove bridge, the CLI's sources, the app's layers): its name, where it sits, the model
// to decode it as, its ROS frame and, once read, its unit's serial. One lidar is a set of one: it
// has a SourceInfo too, at the identity pose, and outputs keep its names unprefixed
// (named_apart). Plain values, no Boost, so every layer from core/frame up can carry it.
#include <optional>
#include <span>
#include <string>

#include "core/frame/pose.h"
#include "core/protocol/model_profile.h"

namespace ydscope {

struct SourceInfo {
  std::string name;            // letters, digits and _: a ROS namespace and a CSV field as is
  Pose pose;                   // in the common frame; the identity for a lone lidar
  std::optional<Model> model;  // decode as; empty: what the device or the recording says
  std::string frame_id = {};   // its ROS frame; empty: its name
  std::string serial = {};     // the unit's serial (A5 90); empty until known

  // The frame its messages carry and its transform names.
  const std::string& frame() const { return frame_id.empty() ? name : frame_id; }
  friend bool operator==(const SourceInfo&, const SourceInfo&) = default;
};

// Whether the sources are told apart by name (/NAME/scan, NAME/scan_hz, a version-2 recording):
// a set of one keeps the names one lidar has always had (/scan, scan_hz, version 1).
inline bool named_apart(std::span<const SourceInfo> sources) { return sources.size() > 1; }

}  // namespace ydscope
