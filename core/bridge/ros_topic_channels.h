#pragma once
// The bridge's channels: one per ROS topic the encoder writes (core/export/ros_topic_encoder.h),
// with the same ros2msg schemas as the MCAP files. Ids start at 1 (0 reads as "unset" in clients).
#include <cstdint>
#include <string>
#include <vector>

#include "core/bridge/foxglove_server.h"
#include "core/export/ros_topic_encoder.h"

namespace ydscope::foxglove {

inline std::uint32_t channel_id(RosTopic topic) { return static_cast<std::uint32_t>(topic) + 1; }

inline std::vector<ServerChannel> ros_topic_channels() {
  std::vector<ServerChannel> out;
  for (const RosTopicInfo& t : ros_topics())
    out.push_back({channel_id(t.topic), std::string(t.name), std::string(t.schema->name), std::string(t.schema->text)});
  return out;
}

}  // namespace ydscope::foxglove
