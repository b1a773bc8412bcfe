// Issue 29: `serve` watches zones headless. Against the virtual G6 in the booth scene, visitors
// walking along the aisle enter and leave a sector zone in front of the stand; /zones (recorded
// by serve's own --mcap) says so, raised while one is in it and quiet while none is, and a zone
// over the stand's kiosk with the `empty` rule stays quiet. /diagnostics carries the same
// statuses beside the lidar's.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <iterator>
#include <map>
#include <set>
#include <string>

#include "cli/cli_run_support.h"
#include "export/cdr_test_reader.h"
#include "export/mcap_test_reader.h"
#include "support/session_test_support.h"
#include "support/temp_dir.h"

namespace ydscope {
namespace {

struct Status {
  std::uint8_t level = 0;
  std::string name, message;
  std::map<std::string, std::string> values;
};

std::vector<Status> diagnostic_array(const std::vector<std::uint8_t>& data) {
  test::CdrReader r(data);
  r.i32();  // stamp
  r.u32();
  r.str();  // frame_id
  std::vector<Status> out(r.u32());
  for (Status& s : out) {
    s.level = r.u8();
    s.name = r.str();
    s.message = r.str();
    r.str();  // hardware_id
    for (std::uint32_t n = r.u32(); n > 0; --n) {
      std::string key = r.str();
      s.values[key] = r.str();
    }
  }
  return out;
}

TEST(ServeZones, BoothVisitorsRaiseTheAisleZoneOnZonesAndDiagnostics) {
  test::SimOnPty sim(Model::G6, [](SimServerOptions& o) { o.device.scene = "booth"; });
  test::TempDir dir("serve-zones");
  const std::string mcap = (dir.path() / "zones.mcap").string();
  const auto serve = test::run_cli_apart(
      "serve --port '" + sim.port() + "' --baud 512000 --listen 127.0.0.1:0 --seconds 15 --mcap '" + mcap +
      "' --zone aisle:sector:330:30:500:3000 --zone kiosk:polygon:0.3,0.3/1.1,0.3/1.1,1.1/0.3,1.1:empty");
  ASSERT_EQ(serve.status, 0) << serve.out << serve.err;

  std::ifstream in(mcap, std::ios::binary);
  const std::vector<std::uint8_t> bytes{std::istreambuf_iterator<char>(in), {}};
  const test::McapContents contents = test::read_mcap(bytes);
  ASSERT_TRUE(contents.complete);
  std::set<int> aisle_levels;
  std::set<std::string> aisle_occupied;
  std::size_t zone_messages = 0, kiosk_raised = 0, kiosk_seen = 0, zones_in_diagnostics = 0;
  std::uint64_t entries = 0;
  for (const test::ReadMessage& m : contents.messages) {
    const std::string& topic = contents.channels.at(m.channel_id).topic;
    if (topic == "/diagnostics") {
      for (const Status& s : diagnostic_array(m.data)) zones_in_diagnostics += s.name.rfind("ydscope zone: ", 0) == 0;
      continue;
    }
    if (topic != "/zones") continue;
    ++zone_messages;
    const std::vector<Status> statuses = diagnostic_array(m.data);
    ASSERT_EQ(statuses.size(), 2u);
    for (const Status& s : statuses) {
      if (s.name == "ydscope zone: aisle (laser)") {
        aisle_levels.insert(s.level);
        aisle_occupied.insert(s.values.at("occupied"));
        EXPECT_EQ(s.level == 1, s.values.at("occupied") == "true") << s.message;
        entries = std::max<std::uint64_t>(entries, std::stoull(s.values.at("entries")));
      } else {
        EXPECT_EQ(s.name, "ydscope zone: kiosk (laser)");
        ++kiosk_seen;
        kiosk_raised += s.level != 0;
      }
    }
  }
  EXPECT_GE(zone_messages, 10u) << "one a second at least";
  EXPECT_EQ(aisle_levels, (std::set<int>{0, 1})) << "the aisle zone should be raised and quiet in turn";
  EXPECT_GE(entries, 2u) << "visitors entering the aisle zone";
  EXPECT_GT(kiosk_seen, 0u);
  EXPECT_LE(kiosk_raised, 1u) << "the kiosk is there all along (at most the first report, before a lap)";
  EXPECT_GT(zones_in_diagnostics, 0u) << "/diagnostics carries the zones beside the lidar";
}

TEST(ServeZones, AMistakenZoneIsAUsageErrorInOneSentence) {
  const auto serve = test::run_cli_apart("serve --port /nonexistent --zone aisle:sector:330");
  EXPECT_EQ(serve.status, 2) << serve.out << serve.err;
  EXPECT_NE(serve.err.find("--zone: zone 'aisle:sector:330'"), std::string::npos) << serve.err;
}

}  // namespace
}  // namespace ydscope
