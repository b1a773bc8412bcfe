// Faults the session must survive on its own: an unplugged and replugged device, a stalled stream,
// a disconnect and a new connect. Each leaves a link state and a sentence, and laps resume.
#include <gtest/gtest.h>

#include "support/session_test_support.h"

namespace ydscope {
namespace {

using namespace test;

TEST(SessionFaults, UnplugAndReplugRecoversByItself) {
  SimOnPty sim(Model::G6);
  Session session(64);
  session.connect(config_for(sim.port(), Model::G6));
  ASSERT_EQ(take_laps(session, 2), 2u) << describe_snapshot(session.snapshot());

  sim.server().unplug();
  const SessionSnapshot lost =
      session.wait_until([](const SessionSnapshot& s) { return s.state == LinkState::Reconnecting; }, kPatience);
  ASSERT_EQ(lost.state, LinkState::Reconnecting) << describe_snapshot(lost);
  EXPECT_FALSE(lost.message.empty());

  sim.server().replug();
  const SessionSnapshot back = wait_for_state(session, LinkState::Scanning);
  ASSERT_EQ(back.state, LinkState::Scanning) << describe_snapshot(back);
  EXPECT_GE(back.counters.reconnects, 1u);
  Lap lap;
  while (session.laps().try_pop(lap)) {
  }
  EXPECT_EQ(take_laps(session, 3), 3u) << describe_snapshot(session.snapshot());
  EXPECT_EQ(sim.counters().device.ignored_during_scan, 0u);
}

TEST(SessionFaults, APortThatComesBackEndsTheBackoffAtOnce) {
  SimOnPty sim(Model::G6);
  Session session(64);
  SessionConfig config = config_for(sim.port(), Model::G6);
  // A minute between attempts: only the port watch can bring the session back within kPatience.
  config.first_backoff = 60s;
  config.max_backoff = 60s;
  session.connect(config);
  ASSERT_EQ(take_laps(session, 2), 2u) << describe_snapshot(session.snapshot());

  sim.server().unplug();
  const SessionSnapshot lost =
      session.wait_until([](const SessionSnapshot& s) { return s.state == LinkState::Reconnecting; }, kPatience);
  ASSERT_EQ(lost.state, LinkState::Reconnecting) << describe_snapshot(lost);
  EXPECT_NE(lost.message.find("retrying when " + sim.port() + " comes back"), std::string::npos) << lost.message;

  sim.server().replug();
  const SessionSnapshot back = wait_for_state(session, LinkState::Scanning);
  ASSERT_EQ(back.state, LinkState::Scanning) << describe_snapshot(back);
  Lap lap;
  while (session.laps().try_pop(lap)) {
  }
  EXPECT_EQ(take_laps(session, 2), 2u) << describe_snapshot(session.snapshot());
}

TEST(SessionFaults, AStalledStreamIsNoticedAndTheScanRestarts) {
  SimOnPty sim(Model::TG30);
  Session session(64);
  SessionConfig config = config_for(sim.port(), Model::TG30);
  config.stall_timeout = 600ms;
  session.connect(config);
  ASSERT_EQ(take_laps(session, 2), 2u) << describe_snapshot(session.snapshot());
  sim.server().stall(2500ms);
  const SessionSnapshot stalled = session.wait_until(
      [](const SessionSnapshot& s) { return s.state == LinkState::Stalled || s.state == LinkState::Reconnecting; },
      kPatience);
  ASSERT_TRUE(stalled.state == LinkState::Stalled || stalled.state == LinkState::Reconnecting)
      << describe_snapshot(stalled);
  EXPECT_NE(stalled.message.find("no data"), std::string::npos) << stalled.message;
  const SessionSnapshot back = wait_for_state(session, LinkState::Scanning);
  ASSERT_EQ(back.state, LinkState::Scanning) << describe_snapshot(back);
  Lap lap;
  while (session.laps().try_pop(lap)) {
  }
  EXPECT_EQ(take_laps(session, 2), 2u);
}

TEST(SessionFaults, UnplugWithoutReconnectFailsWithASentence) {
  SimOnPty sim(Model::G1);
  Session session;
  SessionConfig config = config_for(sim.port(), Model::G1);
  config.reconnect = false;
  session.connect(config);
  ASSERT_EQ(take_laps(session, 1), 1u);
  sim.server().unplug();
  const SessionSnapshot s = wait_for_state(session, LinkState::Failed);
  ASSERT_EQ(s.state, LinkState::Failed) << describe_snapshot(s);
  EXPECT_NE(s.message.find("unplugged"), std::string::npos) << s.message;
}

TEST(SessionFaults, DisconnectStopsTheDeviceAndConnectStartsAgain) {
  SimOnPty sim(Model::G6);
  Session session;
  session.connect(config_for(sim.port(), Model::G6));
  ASSERT_EQ(take_laps(session, 1), 1u);
  session.disconnect();
  ASSERT_EQ(wait_for_state(session, LinkState::Idle).state, LinkState::Idle);
  DeviceMode mode = DeviceMode::Scanning;
  for (int i = 0; i < 100 && mode != DeviceMode::Idle; ++i) {
    sim.server().with_device([&](VirtualLidar& d) { mode = d.mode(); });
    std::this_thread::sleep_for(20ms);
  }
  EXPECT_EQ(mode, DeviceMode::Idle) << "disconnect leaves the lidar stopped";
  session.connect(config_for(sim.port()));
  ASSERT_EQ(wait_for_state(session, LinkState::Scanning).state, LinkState::Scanning);
  Lap lap;
  while (session.laps().try_pop(lap)) {
  }
  EXPECT_EQ(take_laps(session, 2), 2u);
}

TEST(SessionFaults, ASessionDestroyedMidStartUpDoesNotHangAndLeavesTheLidarUsable) {
  SimOnPty sim(Model::TG15);
  for (int i = 0; i < 5; ++i) {
    Session session;
    session.connect(config_for(sim.port(), Model::TG15));
    // Not a synchronisation: each session is destroyed at a different point of its start-up.
    std::this_thread::sleep_for(std::chrono::milliseconds(7 * i));
  }  // a hang here ends the test by CTest's timeout
  Session session;
  session.connect(config_for(sim.port(), Model::TG15));
  EXPECT_EQ(take_laps(session, 2), 2u) << "the lidar did not come back after the interrupted start-ups: "
                                       << describe_snapshot(session.snapshot());
}

}  // namespace
}  // namespace ydscope
