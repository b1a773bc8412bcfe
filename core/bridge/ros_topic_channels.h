#pragma once
// The bridge's channels: one per ROS topic the encoder writes (core/export/ros_topic_encoder.h),
// with the same ros2msg schemas as the MCAP files. Ids start at 1 (0 reads as "unset" in clients).
// One lidar: its topics are 1..kRosTopicCount, named as ever ("/scan"). Several: lidar i's topics
// are the i-th block of kRosTopicCount ids, named "/NAME/scan". /tf_static comes after them.
#include <algorithm>
#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "core/bridge/foxglove_server.h"
#include "core/export/mcap_recording_export.h"
#include "core/export/ros_schemas.h"
#include "core/export/ros_topic_encoder.h"

namespace ydscope::foxglove {

inline std::uint32_t channel_id(RosTopic topic, std::size_t source = 0) {
  return static_cast<std::uint32_t>(source * kRosTopicCount + static_cast<std::size_t>(topic) + 1);
}
inline std::uint32_t tf_static_channel_id(std::size_t sources) {
  return static_cast<std::uint32_t>((sources < 1 ? 1 : sources) * kRosTopicCount + 1);
}

// `sources`: by source id; none or one is one lidar (/scan), several are named apart (/NAME/scan). Without `link_bytes` (serve
// --no-link-bytes) the link-byte topics are not advertised at all, as in an MCAP file.
inline std::vector<ServerChannel> ros_topic_channels(std::span<const SourceInfo> sources = {}, bool link_bytes = true) {
  std::vector<ServerChannel> out;
  const std::size_t count = std::max<std::size_t>(sources.size(), 1);
  for (std::size_t id = 0; id < count; ++id)
    for (const RosTopicInfo& t : ros_topics())
      if (link_bytes || !is_link_bytes(t.topic))
        out.push_back({channel_id(t.topic, id), source_topic_name(sources, id, t.name), std::string(t.schema->name),
                       std::string(t.schema->text)});
  // Every lidar's mount and unit frame, one lidar's too (core/export/ros_tf.h). Latched, as in
  // ROS: a client that subscribes at any time gets every pose at once.
  const RosSchema& tf = tf_message_schema();
  out.push_back({tf_static_channel_id(count), "/tf_static", std::string(tf.name), std::string(tf.text), true});
  return out;
}

}  // namespace ydscope::foxglove
