// /tf_static is latched on the bridge, as a transient-local topic is in ROS: a client that
// subscribes after the poses were published gets the newest of them the moment it subscribes,
// while an ordinary topic's earlier messages are not replayed.
#include <chrono>
#include <memory>
#include <vector>

#include <gtest/gtest.h>

#include "support/ws_test_client.h"
#include "core/bridge/foxglove_server.h"
#include "core/bridge/ros_topic_channels.h"

namespace ydscope {
namespace {

using namespace std::chrono_literals;

TEST(LatchedTopic, ALateSubscriberToTfStaticGetsTheNewestPosesAtOnce) {
  const std::vector<SourceInfo> sources{{"front", {}, {}}, {"back", {}, {}}};
  foxglove::ServerOptions options;
  options.host = "127.0.0.1";
  options.port = 0;
  foxglove::FoxgloveServer server(options, foxglove::ros_topic_channels(sources), nullptr);
  std::string error;
  ASSERT_TRUE(server.start(error)) << error;
  const std::uint32_t tf = foxglove::tf_static_channel_id(sources.size());
  const auto payload = [](std::uint8_t tag) { return std::make_shared<const std::vector<std::uint8_t>>(4, tag); };

  server.publish(tf, 1000, payload(1));
  server.publish(tf, 2000, payload(2));  // the poses as they are now
  server.publish(foxglove::channel_id(RosTopic::Scan, 0), 2500, payload(3));
  server.clients();  // waits for the server's thread: the publishes above are done

  for (int client_number = 0; client_number < 2; ++client_number) {
    SCOPED_TRACE("client " + std::to_string(client_number));
    test::WsTestClient client(server.port());
    ASSERT_TRUE(client.subscribe(7, "/front/scan"));
    ASSERT_TRUE(client.subscribe(8, "/tf_static"));
    const auto poses = client.read_binary(5s);
    ASSERT_TRUE(poses) << "no /tf_static for a client that subscribed after it was published";
    EXPECT_EQ(poses->subscription, 8u);
    EXPECT_EQ(poses->log_time_ns, 2000u);
    EXPECT_EQ(poses->payload, std::vector<std::uint8_t>(4, 2));
    // /front/scan is not latched: its earlier lap is not sent; the next one is.
    server.publish(foxglove::channel_id(RosTopic::Scan, 0), 3000, payload(4));
    const auto scan = client.read_binary(5s);
    ASSERT_TRUE(scan);
    EXPECT_EQ(scan->subscription, 7u);
    EXPECT_EQ(scan->log_time_ns, 3000u);
  }
  server.stop();
}

}  // namespace
}  // namespace ydscope
