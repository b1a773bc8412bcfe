// The bridge advertises what the MCAP files hold: with --no-link-bytes (issue 28) neither file nor
// server offers the link-byte topics, for one lidar or several, and the other topics keep their ids.
#include <gtest/gtest.h>

#include <algorithm>
#include <string>
#include <vector>

#include "core/bridge/ros_topic_channels.h"

namespace ydscope {
namespace {

std::vector<std::string> topic_names(const std::vector<foxglove::ServerChannel>& channels) {
  std::vector<std::string> names;
  for (const foxglove::ServerChannel& channel : channels) names.push_back(channel.topic);
  return names;
}

bool has(const std::vector<std::string>& names, const std::string& name) {
  return std::find(names.begin(), names.end(), name) != names.end();
}

TEST(RosTopicChannels, WithoutLinkBytesNoLinkByteTopicIsAdvertised) {
  const auto all = topic_names(foxglove::ros_topic_channels());
  EXPECT_TRUE(has(all, "/ydscope/device_bytes"));
  EXPECT_TRUE(has(all, "/ydscope/host_bytes"));
  const auto channels = foxglove::ros_topic_channels({}, /*link_bytes=*/false);
  const auto names = topic_names(channels);
  EXPECT_FALSE(has(names, "/ydscope/device_bytes"));
  EXPECT_FALSE(has(names, "/ydscope/host_bytes"));
  ASSERT_TRUE(has(names, "/scan"));
  for (const foxglove::ServerChannel& channel : channels) {
    if (channel.topic == "/scan") {
      EXPECT_EQ(channel.id, foxglove::channel_id(RosTopic::Scan));
    }
  }
}

TEST(RosTopicChannels, SeveralLidarsWithoutLinkBytesKeepTheirOtherTopicsAndTfStatic) {
  const std::vector<SourceInfo> sources{{"front", {}, std::nullopt}, {"back", {}, std::nullopt}};
  const auto names = topic_names(foxglove::ros_topic_channels(sources, /*link_bytes=*/false));
  for (const std::string lidar : {"front", "back"}) {
    EXPECT_TRUE(has(names, "/" + lidar + "/scan")) << lidar;
    EXPECT_TRUE(has(names, "/" + lidar + "/diagnostics")) << lidar;
    for (const std::string& name : names) EXPECT_EQ(name.find("bytes"), std::string::npos) << name;
  }
  EXPECT_TRUE(has(names, "/tf_static"));
}

}  // namespace
}  // namespace ydscope
