// The user's settings outlive a reconnect: a replugged unit is back at its power-on values, and
// the session sets it back to what the user set before its scan resumes, and says so, or says
// what it could not put back.
#include <gtest/gtest.h>

#include <atomic>
#include <map>

#include "core/link/serial_link.h"
#include "session/reply_rewriter.h"
#include "support/session_test_support.h"

namespace ydscope {
namespace {

using namespace test;

struct UnitState {
  std::uint32_t scan_centihz = 0;
  std::uint16_t ranging_khz = 0;
  bool protection = false;
};

UnitState unit_state(SimOnPty& sim) {
  UnitState state;
  sim.server().with_device([&](VirtualLidar& d) {
    state = {d.scan_centihz(), d.ranging_khz(), d.power_down_protection()};
  });
  return state;
}

// Unplugs the unit (it loses power) and plugs it back; the snapshot once the session scans again.
SessionSnapshot replug(SimOnPty& sim, Session& session) {
  sim.server().unplug();
  const SessionSnapshot lost = wait_for_state(session, LinkState::Reconnecting);
  EXPECT_EQ(lost.state, LinkState::Reconnecting) << describe_snapshot(lost);
  sim.server().replug();
  return wait_for_state(session, LinkState::Scanning);
}

TEST(SessionSettings, AReplugGetsTheUsersSettingsBackBeforeTheScanResumes) {
  SimOnPty sim(Model::G6);
  const ModelProfile& g6 = profile_for(Model::G6);
  Session session(64);
  session.connect(config_for(sim.port(), Model::G6));
  ASSERT_EQ(wait_for_state(session, LinkState::Scanning).state, LinkState::Scanning);
  // Values the unit does not power on with, so only re-applying them can bring them back.
  ASSERT_NE(g6.default_scan_hz, 10.0);
  ASSERT_NE(g6.default_ranging_khz, 4);
  ASSERT_TRUE(run_command([&](CommandCallback done) { session.set_scan_hz(10.0, done); }).ok);
  ASSERT_TRUE(run_command([&](CommandCallback done) { session.set_ranging_khz(4, done); }).ok);
  ASSERT_TRUE(run_command([&](CommandCallback done) { session.set_power_down_protection(true, done); }).ok);

  const SessionSnapshot back = replug(sim, session);
  ASSERT_EQ(back.state, LinkState::Scanning) << describe_snapshot(back);
  ASSERT_GE(sim.counters().server.replugs, 1u);
  EXPECT_EQ(back.message, "reconnected; re-applied scan 10.00 Hz, ranging 4 kHz, power-down protection on");
  // The unit itself holds them again, not only the snapshot.
  const UnitState unit = unit_state(sim);
  EXPECT_EQ(unit.scan_centihz, 1000u);
  EXPECT_EQ(unit.ranging_khz, 4);
  EXPECT_TRUE(unit.protection);
  EXPECT_NEAR(back.scan_hz.value_or(0), 10.0, 0.001);
  EXPECT_EQ(back.ranging_khz, 4);
  EXPECT_EQ(back.power_down_protection, true);
  Lap lap;
  while (session.laps().try_pop(lap)) {
  }
  EXPECT_EQ(take_laps(session, 2), 2u) << describe_snapshot(session.snapshot());
}

TEST(SessionSettings, ASettingThatCannotBePutBackIsSaidAndTheScanStillResumes) {
  SimOnPty sim(Model::G6);
  const ModelProfile& g6 = profile_for(Model::G6);
  const std::uint16_t wanted = g6.ranging_khz[1];
  ASSERT_NE(wanted, g6.ranging_khz[0]);
  ASSERT_NE(wanted, g6.default_ranging_khz);
  std::map<std::uint8_t, int> sent;  // the rewriter's count, unused here
  auto opens = std::make_shared<std::atomic<int>>(0);
  SessionConfig config = config_for(sim.port(), Model::G6);
  const std::string port = sim.port();
  // From the second connection on, every ranging answer says code 0: cycling never reaches `wanted`.
  config.open_link = [port, opens, &sent](boost::asio::io_context& io, std::uint32_t baud,
                                          std::string& error) -> std::unique_ptr<ByteLink> {
    auto serial = SerialLink::open(io, port, baud, error);
    if (!serial || opens->fetch_add(1) == 0) return serial;
    return std::make_unique<ReplyRewriter>(std::move(serial), ReplyRewriter::Lies{{0xD0, {{0, 0}}}, {0xD1, {{0, 0}}}},
                                           sent);
  };
  Session session(64);
  session.connect(config);
  ASSERT_EQ(wait_for_state(session, LinkState::Scanning).state, LinkState::Scanning);
  ASSERT_TRUE(run_command([&](CommandCallback done) { session.set_ranging_khz(wanted, done); }).ok);

  const SessionSnapshot back = replug(sim, session);
  ASSERT_EQ(back.state, LinkState::Scanning) << describe_snapshot(back);
  EXPECT_NE(back.message.find("reconnected; could not re-apply ranging " + std::to_string(wanted) + " kHz ("),
            std::string::npos)
      << back.message;
  // The value in force is what the unit reads back, not what the user wanted.
  EXPECT_EQ(back.ranging_khz, g6.ranging_khz[0]);
  Lap lap;
  while (session.laps().try_pop(lap)) {
  }
  EXPECT_EQ(take_laps(session, 2), 2u) << describe_snapshot(session.snapshot());
}

TEST(SessionSettings, AnotherPortIsAnotherLidarWhoseSettingsAreItsOwn) {
  SimOnPty first(Model::G6), second(Model::G6);
  Session session(64);
  session.connect(config_for(first.port(), Model::G6));
  ASSERT_EQ(wait_for_state(session, LinkState::Scanning).state, LinkState::Scanning);
  ASSERT_TRUE(run_command([&](CommandCallback done) { session.set_ranging_khz(4, done); }).ok);
  session.connect(config_for(second.port(), Model::G6));
  const auto on_second = [&](const SessionSnapshot& s) {
    return s.state == LinkState::Scanning && s.link.find(second.port()) != std::string::npos;
  };
  const SessionSnapshot s = session.wait_until(on_second, kPatience);
  ASSERT_TRUE(on_second(s)) << describe_snapshot(s);
  EXPECT_EQ(s.ranging_khz, profile_for(Model::G6).default_ranging_khz);
  EXPECT_EQ(unit_state(second).ranging_khz, profile_for(Model::G6).default_ranging_khz);
  // Power-down protection is reported from the start: off, the manuals' power-on default.
  EXPECT_EQ(s.power_down_protection, false);
}

}  // namespace
}  // namespace ydscope
