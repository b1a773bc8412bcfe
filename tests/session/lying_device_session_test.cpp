// A device whose answers lie, through the whole session: the virtual lidar's replies are
// rewritten on their way to the host, so the session meets a ranging code outside the model's
// table, a ranging frequency that never changes however often it is cycled, and device-info
// fields no model has. Each ends with a sentence, after a bounded number of commands: no field a
// device sends decides how long the session keeps asking.
#include <gtest/gtest.h>

#include <algorithm>
#include <map>
#include <string>

#include "core/link/serial_link.h"
#include "session/reply_rewriter.h"
#include "support/session_test_support.h"

namespace ydscope {
namespace {

using namespace test;

SessionConfig lying_config(const SimOnPty& sim, Model model, ReplyRewriter::Lies lies,
                           std::map<std::uint8_t, int>& sent) {
  SessionConfig config = config_for(sim.port(), model, /*scan=*/false);
  const std::string port = sim.port();
  config.open_link = [port, lies, &sent](boost::asio::io_context& io, std::uint32_t baud,
                                         std::string& error) -> std::unique_ptr<ByteLink> {
    auto serial = SerialLink::open(io, port, baud, error);
    if (!serial) return nullptr;
    return std::make_unique<ReplyRewriter>(std::move(serial), lies, sent);
  };
  return config;
}

constexpr std::uint8_t kRangingCycle = 0xD0;
constexpr std::uint8_t kRangingGet = 0xD1;

TEST(LyingDeviceSession, ARangingFrequencyThatNeverChangesEndsTheCyclingWithASentence) {
  SimOnPty sim(Model::G6);
  std::map<std::uint8_t, int> sent;  // written on the I/O thread, read once the session is gone
  const ModelProfile& g6 = profile_for(Model::G6);
  const std::uint16_t stuck = g6.ranging_khz[0];
  const std::uint16_t target = g6.ranging_khz[g6.ranging_khz.size() - 1];
  ASSERT_NE(stuck, target);
  CommandResult result;
  {
    Session session;
    // Every ranging answer says code 0, whatever the device really did.
    session.connect(lying_config(sim, Model::G6, {{kRangingCycle, {{0, 0}}}, {kRangingGet, {{0, 0}}}}, sent));
    ASSERT_EQ(wait_for_state(session, LinkState::Ready).state, LinkState::Ready)
        << describe_snapshot(session.snapshot());
    result = run_command([&](CommandCallback done) { session.set_ranging_khz(target, std::move(done)); });
  }
  EXPECT_FALSE(result.ok);
  EXPECT_NE(result.message.find("reads back " + std::to_string(stuck) + " kHz after cycling"), std::string::npos)
      << result.message;
  // One cycle per table entry reaches any value, one more for a slow first answer; retries of a
  // command that went unanswered do not count here (every reply arrived).
  EXPECT_LE(sent[kRangingCycle], static_cast<int>(g6.ranging_khz.size()) + 1);
}

TEST(LyingDeviceSession, ARangingCodeOutsideTheTableIsNamedAndNotCycledOn) {
  SimOnPty sim(Model::TG30);
  std::map<std::uint8_t, int> sent;
  const ModelProfile& tg = profile_for(Model::TG30);
  CommandResult result;
  {
    Session session;
    session.connect(lying_config(sim, Model::TG30, {{kRangingCycle, {{0, 0x7F}}}, {kRangingGet, {{0, 0x7F}}}}, sent));
    ASSERT_EQ(wait_for_state(session, LinkState::Ready).state, LinkState::Ready)
        << describe_snapshot(session.snapshot());
    result = run_command([&](CommandCallback done) { session.set_ranging_khz(tg.ranging_khz[0], std::move(done)); });
  }
  EXPECT_FALSE(result.ok);
  EXPECT_NE(result.message.find("not in TG30's table"), std::string::npos) << result.message;
  EXPECT_LE(sent[kRangingCycle], static_cast<int>(tg.ranging_khz.size()) + 1);
}

TEST(LyingDeviceSession, DeviceInfoFieldsNoModelHasAreShownNotTrusted) {
  SimOnPty sim(Model::G6);
  std::map<std::uint8_t, int> sent;
  // A5 90's payload: model code, firmware (2 bytes), hardware, serial (16 bytes).
  ReplyRewriter::Lies lies{{0x90, {{0, 0xEE}, {1, 0xFF}, {2, 0xFF}, {3, 0xFF}}}};
  for (std::size_t i = 4; i < 20; ++i) lies[0x90][i] = 0xFF;
  Session session;
  session.connect(lying_config(sim, Model::G6, lies, sent));
  const SessionSnapshot s = wait_for_state(session, LinkState::Ready);
  ASSERT_EQ(s.state, LinkState::Ready) << describe_snapshot(s);
  ASSERT_TRUE(s.device.has_value());
  EXPECT_EQ(s.device->model_code, 0xEE);
  EXPECT_EQ(s.device->firmware.major, 0xFF);
  EXPECT_LE(s.device->serial.size(), 32u);
  EXPECT_EQ(s.device->profile->model, Model::G6) << "the model asked for, not one made up from the code";
  EXPECT_NE(s.message.find("238"), std::string::npos) << "the unknown code is named: " << s.message;
}

}  // namespace
}  // namespace ydscope
