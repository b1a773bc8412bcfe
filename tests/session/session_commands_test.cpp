// Commands while scanning, against the virtual lidar: each one stops, drains, asks, verifies by
// read-back and resumes; the device never sees anything but A5 65 while it scans.
#include <gtest/gtest.h>

#include "support/session_test_support.h"

namespace ydscope {
namespace {

using namespace test;

struct Scanning {
  explicit Scanning(Model model, const std::function<void(SimServerOptions&)>& tweak = {}) : sim(model, tweak) {
    session.connect(config_for(sim.port(), model));
    const SessionSnapshot s = wait_for_state(session, LinkState::Scanning);
    EXPECT_EQ(s.state, LinkState::Scanning) << describe_snapshot(s);
  }
  DeviceCounters device() { return sim.counters().device; }
  SimOnPty sim;
  Session session;
};

TEST(SessionCommands, ScanFrequencyTargetIsReachedAndReadBack) {
  Scanning g6(Model::G6);
  for (const double target : {10.0, 7.3, 12.0}) {
    const CommandResult r = run_command([&](CommandCallback done) { g6.session.set_scan_hz(target, done); });
    ASSERT_TRUE(r.ok) << r.what << ": " << r.message;
    ASSERT_TRUE(r.scan_hz.has_value());
    EXPECT_NEAR(*r.scan_hz, target, 0.051);
    std::uint32_t centihz = 0;
    g6.sim.server().with_device([&](VirtualLidar& d) { centihz = d.scan_centihz(); });
    EXPECT_NEAR(centihz / 100.0, target, 0.051);
    EXPECT_NEAR(*g6.session.snapshot().scan_hz, target, 0.051);
  }
  // The scan resumed: laps keep coming after the commands.
  Lap lap;
  while (g6.session.laps().try_pop(lap)) {
  }
  EXPECT_EQ(take_laps(g6.session, 3), 3u);
  EXPECT_EQ(g6.session.snapshot().state, LinkState::Scanning);
  EXPECT_EQ(g6.device().ignored_during_scan, 0u) << "a command other than A5 65 reached the scanning device";
  EXPECT_EQ(g6.session.snapshot().counters.refused_commands, 0u);
}

TEST(SessionCommands, ScanFrequencyOutsideTheModelRangeIsRefusedWithASentence) {
  Scanning g1(Model::G1);
  const CommandResult r = run_command([&](CommandCallback done) { g1.session.set_scan_hz(40.0, done); });
  EXPECT_FALSE(r.ok);
  EXPECT_NE(r.message.find("outside"), std::string::npos) << r.message;
  EXPECT_EQ(take_laps(g1.session, 2), 2u);
}

TEST(SessionCommands, RangingTargetIsReachedByCycling) {
  Scanning tg(Model::TG15);
  for (const std::uint16_t target : std::initializer_list<std::uint16_t>{4, 8, 9, 4}) {
    const CommandResult r = run_command([&](CommandCallback done) { tg.session.set_ranging_khz(target, done); });
    ASSERT_TRUE(r.ok) << r.what << ": " << r.message;
    EXPECT_EQ(r.ranging_khz, target);
    std::uint16_t khz = 0;
    tg.sim.server().with_device([&](VirtualLidar& d) { khz = d.ranging_khz(); });
    EXPECT_EQ(khz, target);
  }
  EXPECT_EQ(take_laps(tg.session, 2), 2u);
  EXPECT_EQ(tg.device().ignored_during_scan, 0u);
}

TEST(SessionCommands, G1RangingIsReadOnly) {
  Scanning g1(Model::G1);
  const CommandResult r = run_command([&](CommandCallback done) { g1.session.set_ranging_khz(5, done); });
  EXPECT_FALSE(r.ok);
  EXPECT_NE(r.message.find("read-only"), std::string::npos) << r.message;
  const CommandResult bad = run_command([&](CommandCallback done) { g1.session.set_ranging_khz(7, done); });
  EXPECT_FALSE(bad.ok);
  EXPECT_NE(bad.message.find("not a ranging frequency"), std::string::npos) << bad.message;
}

TEST(SessionCommands, HealthFallsBackToTheOtherCommandOnceAndRemembers) {
  // This G6 answers only A5 92, as some units in the field do.
  Scanning g6(Model::G6, [](SimServerOptions& o) { o.device.health_quirk = true; });
  const SessionSnapshot start = g6.session.snapshot();
  ASSERT_TRUE(start.health.has_value()) << start.message;
  EXPECT_EQ(start.health->command, Command::HealthStatusBits);
  const std::uint64_t unanswered = g6.device().unsupported;
  const CommandResult r = run_command([&](CommandCallback done) { g6.session.refresh_health(done); });
  ASSERT_TRUE(r.ok) << r.message;
  ASSERT_TRUE(r.health.has_value());
  EXPECT_EQ(r.health->command, Command::HealthStatusBits);
  EXPECT_EQ(g6.device().unsupported, unanswered) << "the remembered command is asked first";
}

TEST(SessionCommands, HealthReportsRaisedBits) {
  Scanning g1(Model::G1, [](SimServerOptions& o) { o.device.faults.health_bits = kG1HealthEncoder | kG1HealthLd; });
  const CommandResult r = run_command([&](CommandCallback done) { g1.session.refresh_health(done); });
  ASSERT_TRUE(r.ok) << r.message;
  ASSERT_TRUE(r.health.has_value());
  EXPECT_EQ(r.health->command, Command::HealthStatusBits);
  EXPECT_EQ(r.health->status & 0x3F, kG1HealthEncoder | kG1HealthLd);
  EXPECT_NE(r.health->summary.find("encoder"), std::string::npos) << r.health->summary;
}

TEST(SessionCommands, PowerDownProtectionKeepsTheScanAlivePastThreeSeconds) {
  Scanning g6(Model::G6);
  const CommandResult r = run_command([&](CommandCallback done) { g6.session.set_power_down_protection(true, done); });
  ASSERT_TRUE(r.ok) << r.message;
  EXPECT_EQ(r.power_down_protection, true);
  bool protection = false;
  g6.sim.server().with_device([&](VirtualLidar& d) { protection = d.power_down_protection(); });
  ASSERT_TRUE(protection);
  // Wait well past the device's 3 s watchdog, then laps must still be flowing.
  std::this_thread::sleep_for(4500ms);
  Lap lap;
  while (g6.session.laps().try_pop(lap)) {
  }
  EXPECT_EQ(take_laps(g6.session, 3), 3u);
  const DeviceCounters device = g6.device();
  EXPECT_EQ(device.power_down_stops, 0u);
  EXPECT_GE(device.keepalives, 3u);
  EXPECT_EQ(device.ignored_during_scan, 0u);
  // And off again: the keepalive stops with it.
  const CommandResult off =
      run_command([&](CommandCallback done) { g6.session.set_power_down_protection(false, done); });
  ASSERT_TRUE(off.ok) << off.message;
  EXPECT_EQ(off.power_down_protection, false);
}

TEST(SessionCommands, NothingButStopReachesAScanningDevice) {
  Scanning tg(Model::TG50);
  // Many intents at once, from another thread, while laps flow.
  std::vector<std::future<CommandResult>> results;
  for (int i = 0; i < 3; ++i) {
    auto p1 = std::make_shared<std::promise<CommandResult>>();
    results.push_back(p1->get_future());
    tg.session.set_scan_hz(8.0 + i, [p1](const CommandResult& r) { p1->set_value(r); });
    auto p2 = std::make_shared<std::promise<CommandResult>>();
    results.push_back(p2->get_future());
    tg.session.refresh_health([p2](const CommandResult& r) { p2->set_value(r); });
    auto p3 = std::make_shared<std::promise<CommandResult>>();
    results.push_back(p3->get_future());
    tg.session.set_ranging_khz(static_cast<std::uint16_t>(i % 2 ? 4 : 8),
                               [p3](const CommandResult& r) { p3->set_value(r); });
  }
  for (auto& f : results) {
    ASSERT_EQ(f.wait_for(kPatience), std::future_status::ready);
    const CommandResult r = f.get();
    EXPECT_TRUE(r.ok) << r.what << ": " << r.message;
  }
  EXPECT_EQ(take_laps(tg.session, 2), 2u);
  EXPECT_EQ(tg.device().ignored_during_scan, 0u);
  EXPECT_EQ(tg.session.snapshot().counters.refused_commands, 0u);
  EXPECT_GT(tg.device().scans_started, 9u) << "every command was wrapped in stop ... resume";
}

TEST(SessionCommands, IntentsWithoutAConnectionAnswerAtOnce) {
  Session session;
  const CommandResult r = run_command([&](CommandCallback done) { session.set_scan_hz(10.0, done); });
  EXPECT_FALSE(r.ok);
  EXPECT_NE(r.message.find("not connected"), std::string::npos) << r.message;
}

}  // namespace
}  // namespace ydscope
