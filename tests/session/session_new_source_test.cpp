// A new connection starts clean: what the snapshot says about the device (health answer, set scan
// rate, counters) belongs to the connection that learned it, not to the one before.
#include <chrono>
#include <string>

#include <gtest/gtest.h>

#include "core/link/replay_link.h"
#include "core/session/session.h"
#include "core/sim/sim_server.h"
#include "test_data.h"

namespace ydscope {
namespace {

TEST(SessionNewSource, ReplayAfterALiveG1ShowsNoneOfTheG1sAnswers) {
  SimServerOptions options;
  options.device.model = Model::G1;
  options.device.scene = "room";
  options.device.faults.health_bits = 0x03;  // so the G1's health answer is unmistakable
  SimServer sim(options);
  sim.start();

  Session session(16);
  SessionConfig live;
  live.address = sim.device_path();
  live.reconnect = false;
  session.connect(live);
  const auto g1 = session.wait_until(
      [](const SessionSnapshot& s) {
        return (s.state == LinkState::Scanning && s.health && s.counters.laps > 2) || s.state == LinkState::Failed;
      },
      std::chrono::seconds(20));
  ASSERT_EQ(g1.state, LinkState::Scanning) << g1.message;
  ASSERT_TRUE(g1.health);
  ASSERT_EQ(g1.health->status, 0x03);
  ASSERT_TRUE(g1.scan_hz);
  ASSERT_GT(g1.counters.bytes_received, 0u);

  const std::string file = (test::assets_dir() / "demo-g6.ydrec").string();
  SessionConfig replay;
  replay.address = file;
  replay.model = Model::G6;
  replay.reconnect = false;
  replay.open_link = [file](boost::asio::io_context& io, std::uint32_t,
                            std::string& error) -> std::unique_ptr<ByteLink> {
    return ReplayLink::open(io, file, {.speed = 1}, error);
  };
  session.connect(replay);
  const auto g6 = session.wait_until(
      [](const SessionSnapshot& s) {
        return (s.state == LinkState::Scanning && s.device && s.device->profile->model == Model::G6) ||
               s.state == LinkState::Failed;
      },
      std::chrono::seconds(20));
  ASSERT_EQ(g6.state, LinkState::Scanning) << g6.message;
  EXPECT_FALSE(g6.health) << "the replay shows the G1's health answer: " << g6.health->summary;
  EXPECT_FALSE(g6.scan_hz) << "the replay shows the G1's set rate";
  EXPECT_FALSE(g6.last_result);
  session.disconnect();
}

TEST(SessionNewSource, CountersStartAtZeroOnANewConnection) {
  SimServerOptions options;
  options.device.model = Model::G6;
  options.device.scene = "room";
  SimServer first(options);
  first.start();
  Session session(16);
  SessionConfig config;
  config.address = first.device_path();
  config.reconnect = false;
  session.connect(config);
  const auto before =
      session.wait_until([](const SessionSnapshot& s) { return s.counters.laps >= 6 || s.state == LinkState::Failed; },
                         std::chrono::seconds(20));
  ASSERT_GE(before.counters.laps, 6u) << before.message;
  session.disconnect();
  session.wait_until([](const SessionSnapshot& s) { return s.state == LinkState::Idle; }, std::chrono::seconds(10));

  SimServer second(options);
  second.start();
  config.address = second.device_path();
  session.connect(config);
  // Right after the probe the new connection has counted at most a lap or two.
  const auto after = session.wait_until(
      [](const SessionSnapshot& s) { return s.state == LinkState::Scanning || s.state == LinkState::Failed; },
      std::chrono::seconds(20));
  ASSERT_EQ(after.state, LinkState::Scanning) << after.message;
  EXPECT_LT(after.counters.laps, before.counters.laps);
  session.disconnect();
}

}  // namespace
}  // namespace ydscope
