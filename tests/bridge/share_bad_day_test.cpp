// A shared lidar on a bad day, as a Foxglove client sees it: after an unplugged cable the clients
// are told the parameter values in force, every parameter serve lists is returned, and
// /diagnostics keeps coming through an outage, saying so, with a level that follows the lidar's
// state now rather than its worst moment; the MCAP recorded alongside holds the same reports.
#include <gtest/gtest.h>

#include <functional>
#include <optional>
#include <string>

#include "support/ws_test_client.h"
#include "core/bridge/session_share.h"
#include "export/diagnostics_reader.h"
#include "export/mcap_test_reader.h"
#include "support/raw_recording.h"
#include "support/session_test_support.h"

namespace ydscope {
namespace {

using namespace test;

bool has(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

// Reads messages until `wanted` holds for one (returned), for at most `patience`.
std::optional<WsMessage> read_until(WsTestClient& client, const std::function<bool(const WsMessage&)>& wanted,
                                    std::chrono::milliseconds patience = kPatience) {
  const auto deadline = std::chrono::steady_clock::now() + patience;
  while (std::chrono::steady_clock::now() < deadline && !client.closed()) {
    const auto message = client.read(std::chrono::seconds(2));
    if (message && wanted(*message)) return message;
  }
  return std::nullopt;
}

// The parameterValues answering request `id`.
std::optional<std::string> answer_to(WsTestClient& client, const std::string& id) {
  const auto message = read_until(client, [&](const WsMessage& m) {
    return m.text && has(m.json, R"("op":"parameterValues")") && has(m.json, R"("id":")" + id + "\"");
  });
  if (!message) return std::nullopt;
  return message->json;
}

struct Shared {
  // `mcap_path`: also record the topics there (serve --mcap, record --mcap).
  explicit Shared(Model model, std::string mcap_path = {}) : sim(model) {
    ShareOptions options;
    options.server.port = 0;
    options.mcap_path = std::move(mcap_path);
    std::string error;
    share = SessionShare::start({{&session, {}}}, options, error);
    EXPECT_TRUE(share) << error;
    session.connect(config_for(sim.port(), model));
    const SessionSnapshot s = wait_for_state(session, LinkState::Scanning);
    EXPECT_EQ(s.state, LinkState::Scanning) << describe_snapshot(s);
  }
  // Pulls the cable (the unit loses power) and waits until the session knows.
  void unplug() {
    sim.server().unplug();
    const SessionSnapshot s = wait_for_state(session, LinkState::Reconnecting);
    EXPECT_EQ(s.state, LinkState::Reconnecting) << describe_snapshot(s);
  }
  SimOnPty sim;
  Session session{4};
  std::unique_ptr<SessionShare> share;
};

TEST(ShareBadDay, AfterAReplugTheClientsAreToldTheValuesInForce) {
  Shared lidar(Model::G6);
  ASSERT_TRUE(lidar.share);
  WsTestClient client(lidar.share->port());
  ASSERT_TRUE(client.send_text(R"({"op":"getParameters","parameterNames":[],"id":"before"})"));
  const auto before = answer_to(client, "before");
  ASSERT_TRUE(before) << "no answer to getParameters";
  // Every parameter serve --help lists, power-down protection too (off: the power-on default).
  EXPECT_TRUE(has(*before, R"({"name":"power_down_protection","value":false})")) << *before;
  for (const char* name : {"scan_hz", "ranging_khz", "filter_specular", "filter_ambient"})
    EXPECT_TRUE(has(*before, std::string(R"({"name":")") + name + "\"")) << name << " missing: " << *before;

  ASSERT_TRUE(client.send_text(
      R"({"op":"setParameters","parameters":[{"name":"scan_hz","value":10},{"name":"ranging_khz","value":4},)"
      R"({"name":"filter_specular","value":true}],"id":"set"})"));
  for (int answers = 0; answers < 3; ++answers) ASSERT_TRUE(answer_to(client, "set")) << "a set went unanswered";
  ASSERT_TRUE(client.send_text(R"({"op":"subscribeParameterUpdates","parameterNames":[]})"));

  lidar.unplug();
  lidar.sim.server().replug();
  // Unasked (no id): the values the unit holds again, so a panel never shows the power-on ones.
  const auto told = read_until(client, [](const WsMessage& m) {
    return m.text && has(m.json, R"("op":"parameterValues")") && !has(m.json, R"("id")");
  });
  ASSERT_TRUE(told) << "the clients were not told the values after the reconnect: "
                    << describe_snapshot(lidar.session.snapshot());
  EXPECT_TRUE(has(told->json, R"({"name":"scan_hz","value":10,)")) << told->json;
  EXPECT_TRUE(has(told->json, R"({"name":"ranging_khz","value":4,)")) << told->json;
  EXPECT_TRUE(has(told->json, R"({"name":"power_down_protection","value":false})")) << told->json;
  // The filter is the server's own, not the unit's: the replug left it as the client set it.
  EXPECT_TRUE(has(told->json, R"({"name":"filter_specular","value":true})")) << told->json;
  EXPECT_TRUE(lidar.share->stop());
}

TEST(ShareBadDay, OneOfSeveralLidarsIsToldUnderItsOwnName) {
  SimOnPty front_sim(Model::G6), back_sim(Model::G6);
  Session front(4), back(4);
  ShareOptions options;
  options.server.port = 0;
  std::string error;
  auto share =
      SessionShare::start({{&front, SourceInfo{"front", {}, {}}}, {&back, SourceInfo{"back", {}, {}}}}, options, error);
  ASSERT_TRUE(share) << error;
  front.connect(config_for(front_sim.port(), Model::G6));
  back.connect(config_for(back_sim.port(), Model::G6));
  ASSERT_EQ(wait_for_state(front, LinkState::Scanning).state, LinkState::Scanning);
  ASSERT_EQ(wait_for_state(back, LinkState::Scanning).state, LinkState::Scanning);
  WsTestClient client(share->port());
  ASSERT_TRUE(
      client.send_text(R"({"op":"setParameters","parameters":[{"name":"back/ranging_khz","value":4}],"id":"set"})"));
  ASSERT_TRUE(answer_to(client, "set"));
  ASSERT_TRUE(client.send_text(R"({"op":"subscribeParameterUpdates","parameterNames":[]})"));

  back_sim.server().unplug();
  ASSERT_EQ(wait_for_state(back, LinkState::Reconnecting).state, LinkState::Reconnecting);
  back_sim.server().replug();
  // The update that tells back's values: front's own start-up may still announce its values after
  // the subscription (seen under TSan), and that message is about front, not this replug.
  const auto told = read_until(client, [](const WsMessage& m) {
    return m.text && has(m.json, R"("op":"parameterValues")") && !has(m.json, R"("id")") &&
           !(has(m.json, R"("name":"front/)") && !has(m.json, R"("name":"back/)"));
  });
  ASSERT_TRUE(told) << "the clients were not told back's values: " << describe_snapshot(back.snapshot());
  EXPECT_TRUE(has(told->json, R"({"name":"back/ranging_khz","value":4,)")) << told->json;
  EXPECT_FALSE(has(told->json, R"("name":"ranging_khz")")) << "a name without its lidar: " << told->json;
  EXPECT_FALSE(has(told->json, R"("name":"front/)")) << "front did not reconnect: " << told->json;
  EXPECT_TRUE(share->stop());
}

TEST(ShareBadDay, DiagnosticsFollowTheLidarsStateNowAndKeepComingThroughAnOutage) {
  TempDir dir("bad-day");
  const std::string mcap = (dir.path() / "run.mcap").string();
  Shared lidar(Model::G6, mcap);
  ASSERT_TRUE(lidar.share);
  WsTestClient client(lidar.share->port());
  ASSERT_TRUE(client.subscribe(1, "/diagnostics"));
  // Every report's words agree with its level.
  const auto report = [&](const std::function<bool(const DiagnosticSeen&)>& wanted) {
    std::optional<DiagnosticSeen> found;
    read_until(client, [&](const WsMessage& m) {
      if (m.text || m.subscription != 1) return false;
      const DiagnosticSeen status = diagnostic_status(m.payload);
      EXPECT_EQ(status.level == 0, status.message.rfind("ok", 0) == 0)
          << "level " << int(status.level) << " with: " << status.message;
      if (wanted(status)) found = status;
      return found.has_value();
    });
    return found;
  };

  // Damaged bytes for a while: a warning naming them ...
  FaultConfig corrupt;
  corrupt.corrupt_byte_rate = 0.002;
  lidar.sim.server().with_device([&](VirtualLidar& d) { d.set_faults(corrupt); });
  const auto warned = report([](const DiagnosticSeen& s) { return s.level == 1 && has(s.message, "checksum errors"); });
  ASSERT_TRUE(warned) << "no warning for checksum errors";
  EXPECT_TRUE(has(warned->message, "in the last 5.0 s")) << warned->message;
  // ... which ends once they are past.
  lidar.sim.server().with_device([](VirtualLidar& d) { d.set_faults({}); });
  EXPECT_TRUE(report([](const DiagnosticSeen& s) { return s.level == 0; }))
      << "the level stayed raised after the errors were past";

  // An outage: /diagnostics goes on, an error saying so, until the lidar is back.
  lidar.unplug();
  const std::string outage = "reconnecting to " + lidar.sim.port();
  for (int reports = 0; reports < 3; ++reports) {
    const auto down = report([](const DiagnosticSeen& s) { return s.level == 2; });
    ASSERT_TRUE(down) << "/diagnostics went silent during the outage";
    EXPECT_TRUE(has(down->message, "no data for ")) << down->message;
    EXPECT_TRUE(has(down->message, outage)) << down->message;
  }
  lidar.sim.server().replug();
  EXPECT_TRUE(report([](const DiagnosticSeen& s) { return s.level == 0; }))
      << "the level did not come back after the reconnect: " << describe_snapshot(lidar.session.snapshot());
  ASSERT_TRUE(lidar.share->stop());

  // The file has the outage's reports too, not only the clients.
  const McapContents file = read_mcap(read_file_bytes(mcap));
  std::uint16_t diagnostics = 0;
  for (const auto& [id, channel] : file.channels)
    if (channel.topic == "/diagnostics") diagnostics = id;
  std::size_t outage_reports = 0;
  for (const ReadMessage& m : file.messages)
    if (m.channel_id == diagnostics) {
      const DiagnosticSeen status = diagnostic_status(m.data);
      outage_reports += status.level == 2 && has(status.message, outage) ? 1 : 0;
    }
  EXPECT_GE(outage_reports, 3u);
}

}  // namespace
}  // namespace ydscope
