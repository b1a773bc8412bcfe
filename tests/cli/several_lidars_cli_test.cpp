// ydscope-cli record with several --port, as a user runs it against three virtual lidars: one
// recording holds them all, and replay and decode print every lidar's laps tagged with its name.
// Mistakes in naming or placing the lidars are one sentence and exit status 2.
#include <algorithm>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <map>
#include <string>

#include <gtest/gtest.h>

#include "core/record/recording_reader.h"
#include "cli/cli_run_support.h"
#include "export/cdr_test_reader.h"
#include "export/mcap_test_reader.h"
#include "support/raw_recording.h"
#include "support/session_test_support.h"
#include "support/temp_dir.h"

namespace ydscope {
namespace {

namespace fs = std::filesystem;
using test::count;
using test::run_cli_apart;

class SeveralLidarsCli : public ::testing::Test {
 protected:
  std::string path(const std::string& name) const { return dir_.file(name); }

  test::TempDir dir_{"several"};
};

// Lines of `text` that start with `prefix`, by the value of their "source" field.
std::map<std::string, std::size_t> tagged(const std::string& text, const std::string& prefix) {
  std::map<std::string, std::size_t> by_source;
  std::size_t at = 0;
  while (at < text.size()) {
    const std::size_t end = std::min(text.find('\n', at), text.size());
    const std::string line = text.substr(at, end - at);
    if (line.rfind(prefix, 0) == 0) {
      const std::size_t from = line.find("\"source\":\"");
      const std::string source =
          from == std::string::npos ? "(none)" : line.substr(from + 10, line.find('"', from + 10) - from - 10);
      ++by_source[source];
    }
    at = end + 1;
  }
  return by_source;
}

TEST_F(SeveralLidarsCli, RecordsThreeLidarsAndReplaysEachOnesLapsTagged) {
  test::SimOnPty g1(Model::G1);
  test::SimOnPty g6(Model::G6);
  test::SimOnPty tg30(Model::TG30);
  const std::string out = path("three.ydrec");
  const auto record = run_cli_apart("record --port '" + g1.port() + "' --name left --pose 0.1,0.2,90 --port '" +
                                    g6.port() + "' --name mid --pose 0,0,0 --port '" + tg30.port() +
                                    "' --name right --pose 0,-0.3,180,flip --out '" + out + "' --seconds 2");
  ASSERT_EQ(record.status, 0) << record.out << record.err;
  EXPECT_NE(record.out.find("recorded " + out + ": "), std::string::npos) << record.out;
  EXPECT_NE(record.out.find(", 3 lidars\n"), std::string::npos) << record.out;
  EXPECT_NE(record.out.find("  left: G1 on "), std::string::npos) << record.out;
  EXPECT_NE(record.out.find("  mid: G6 on "), std::string::npos) << record.out;
  EXPECT_NE(record.out.find("  right: TG30 on "), std::string::npos) << record.out;

  // The file: version 2, each source's name, pose and detected model.
  std::string error;
  auto reader = RecordingReader::open(out, error);
  ASSERT_TRUE(reader) << error;
  EXPECT_EQ(reader->version(), kMultiSourceVersion);
  ASSERT_EQ(reader->source_count(), 3u);
  EXPECT_EQ(reader->source_metadata(0).pose, (Pose{0.1, 0.2, 90, false}));
  EXPECT_EQ(reader->source_metadata(2).pose, (Pose{0, -0.3, 180, true}));
  EXPECT_EQ(reader->source_metadata(2).port, tg30.port());
  const auto summary = summarize_recording(out, error);
  ASSERT_TRUE(summary) << error;
  EXPECT_EQ(summary->sources.at(0).metadata.model, "G1");
  EXPECT_EQ(summary->sources.at(1).metadata.model, "G6");
  EXPECT_EQ(summary->sources.at(2).metadata.model, "TG30");
  EXPECT_TRUE(summary->damage.empty());

  const auto replay = run_cli_apart("replay '" + out + "' --speed 0");
  ASSERT_EQ(replay.status, 0) << replay.err;
  const auto laps = tagged(replay.out, "{\"type\":\"lap\"");
  EXPECT_EQ(laps.count("(none)"), 0u) << "a lap without its source";
  for (const char* name : {"left", "mid", "right"}) {
    ASSERT_GT(laps.count(name), 0u) << name << " has no laps:\n" << replay.out.substr(0, 400);
    // Two seconds of a 5-12 Hz lidar: a handful of whole laps at least.
    EXPECT_GE(laps.at(name), 5u) << name;
    const std::string summary_line = "{\"type\":\"summary\",\"source\":\"" + std::string(name) + "\",\"bytes\":";
    EXPECT_EQ(count(replay.out, summary_line), 1u) << replay.out.substr(replay.out.size() - 600);
    EXPECT_NE(record.out.find(std::string(name) + ": "), std::string::npos);
    // record counted the laps a replay gives.
    EXPECT_NE(record.out.find(", " + std::to_string(laps.at(name)) + " laps"), std::string::npos)
        << name << " " << laps.at(name) << "\n"
        << record.out;
  }
  // decode prints the same lines as replay, and CSV gets a source column.
  const auto decode = run_cli_apart("decode '" + out + "'");
  ASSERT_EQ(decode.status, 0) << decode.err;
  EXPECT_EQ(decode.out, replay.out);
  const auto csv = run_cli_apart("decode '" + out + "' --format csv");
  ASSERT_EQ(csv.status, 0) << csv.err;
  EXPECT_EQ(csv.out.rfind("source,lap,t,angle_deg,range_mm,flag\n", 0), 0u) << csv.out.substr(0, 80);
  for (const char* name : {"\nleft,0,", "\nmid,0,", "\nright,0,"})
    EXPECT_NE(csv.out.find(name), std::string::npos) << name;
}

TEST_F(SeveralLidarsCli, RecordsTwoLidarsLiveIntoOneMcapEachUnderItsName) {
  test::SimOnPty g1(Model::G1);
  test::SimOnPty g6(Model::G6);
  const std::string mcap = path("two.mcap");
  const auto record = run_cli_apart(
      "record --port '" + g1.port() + "' --name front --pose 0.2,0,0 --frame-id front_laser --port '" + g6.port() +
      "' --name back --pose -0.2,0,180,flip --frame-id rear_laser --parent-frame robot --mcap '" + mcap +
      "' --seconds 2");
  ASSERT_EQ(record.status, 0) << record.out << record.err;
  EXPECT_EQ(record.out.rfind("wrote " + mcap + ": ", 0), 0u) << record.out;

  // The strict reader (every CRC and index checked): each lidar's topics under its name, laps
  // from both, and /tf_static.
  std::ifstream in(mcap, std::ios::binary);
  const std::vector<std::uint8_t> bytes{std::istreambuf_iterator<char>(in), {}};
  const test::McapContents contents = test::read_mcap(bytes);
  EXPECT_TRUE(contents.complete);
  std::map<std::string, std::size_t> per_topic;
  for (const test::ReadMessage& m : contents.messages) {
    const std::string& topic = contents.channels.at(m.channel_id).topic;
    ++per_topic[topic];
    test::CdrReader r(m.data);
    if (topic == "/front/points" || topic == "/back/scan") {  // each lidar's --frame-id in its headers
      r.i32();
      r.u32();
      EXPECT_EQ(r.str(), topic == "/front/points" ? "front_laser" : "rear_laser");
    }
    if (topic != "/tf_static") continue;
    // Each lidar placed in --parent-frame under its --frame-id, each with its unit frame under it.
    std::vector<std::pair<std::string, std::string>> links;
    for (std::uint32_t n = r.u32(), i = 0; i < n; ++i) {
      r.i32();
      r.u32();
      std::string parent = r.str();
      links.emplace_back(std::move(parent), r.str());
      for (int v = 0; v < 7; ++v) r.take(8, 8);
    }
    EXPECT_EQ(links, (std::vector<std::pair<std::string, std::string>>{{"robot", "front_laser"},
                                                                       {"front_laser", "front_laser_unit"},
                                                                       {"robot", "rear_laser"},
                                                                       {"rear_laser", "rear_laser_unit"}}));
  }
  EXPECT_GE(per_topic["/front/points"], 5u);
  EXPECT_GE(per_topic["/back/points"], 5u);
  EXPECT_EQ(per_topic["/front/scan"], per_topic["/front/points"]);
  EXPECT_EQ(per_topic["/tf_static"], 1u);
  EXPECT_EQ(per_topic.count("/points"), 0u) << "no un-namespaced topic with several lidars";
  const std::size_t laps = per_topic["/front/points"] + per_topic["/back/points"];
  EXPECT_NE(record.out.find(": " + std::to_string(laps) + " laps, "), std::string::npos) << record.out;
}

// A live two-lidar MCAP decodes back like the .ydrec made beside it: each lidar's host bytes
// (every command, the first A5 65 included) and device bytes are the file's, and the messages of
// both lidars are in log-time order in the file.
TEST_F(SeveralLidarsCli, ALiveTwoLidarMcapHoldsEveryByteOfTheRecordingInLogTimeOrder) {
  test::SimOnPty g1(Model::G1);
  test::SimOnPty g6(Model::G6);
  const std::string out = path("two.ydrec");
  const std::string mcap = path("two.mcap");
  const auto record = run_cli_apart("record --port '" + g1.port() + "' --name front --port '" + g6.port() +
                                    "' --name back --out '" + out + "' --mcap '" + mcap + "' --seconds 2");
  ASSERT_EQ(record.status, 0) << record.out << record.err;

  // The .ydrec's bytes, per lidar and direction.
  std::map<std::string, std::vector<std::uint8_t>> recorded;
  std::string error;
  auto reader = RecordingReader::open(out, error);
  ASSERT_TRUE(reader) << error;
  RecordView view;
  while (reader->next(view)) {
    if (view.type == RecordType::Metadata) continue;
    const std::string key = std::string(view.source == 0 ? "/front" : "/back") +
                            (view.type == RecordType::HostToDevice ? "/ydscope/host_bytes" : "/ydscope/device_bytes");
    recorded[key].insert(recorded[key].end(), view.payload.begin(), view.payload.end());
  }

  std::ifstream in(mcap, std::ios::binary);
  const std::vector<std::uint8_t> bytes{std::istreambuf_iterator<char>(in), {}};
  const test::McapContents contents = test::read_mcap(bytes);
  ASSERT_TRUE(contents.complete);
  std::map<std::string, std::vector<std::uint8_t>> carried;
  std::uint64_t previous = 0;
  std::size_t out_of_order = 0;
  for (const test::ReadMessage& m : contents.messages) {
    if (m.log_time < previous) ++out_of_order;
    previous = std::max(previous, m.log_time);
    const std::string& topic = contents.channels.at(m.channel_id).topic;
    if (topic.find("/ydscope/") == std::string::npos) continue;
    test::CdrReader r(m.data);
    r.u32();  // layout.dim
    r.u32();  // layout.data_offset
    const std::uint32_t n = r.u32();
    const std::uint8_t* data = r.take(n);
    carried[topic].insert(carried[topic].end(), data, data + n);
  }
  EXPECT_EQ(out_of_order, 0u) << "messages written after a later one, in file order";
  for (const char* topic : {"/front/ydscope/host_bytes", "/back/ydscope/host_bytes"}) {
    SCOPED_TRACE(topic);
    ASSERT_GE(carried[topic].size(), 2u);
    // Every start-up begins with a stop: the first command of each lidar.
    EXPECT_EQ(carried[topic][0], 0xA5);
    EXPECT_EQ(carried[topic][1], 0x65);
    EXPECT_EQ(carried[topic], recorded[topic]);
  }
  for (const char* topic : {"/front/ydscope/device_bytes", "/back/ydscope/device_bytes"}) {
    SCOPED_TRACE(topic);
    EXPECT_GT(carried[topic].size(), 1000u);
    // Both start with the connection; the files' taps close one after the other, so one may
    // hold a last read more than the other.
    const std::size_t common = std::min(carried[topic].size(), recorded[topic].size());
    EXPECT_GT(common, 1000u);
    EXPECT_TRUE(std::equal(carried[topic].begin(), carried[topic].begin() + static_cast<std::ptrdiff_t>(common),
                           recorded[topic].begin()))
        << carried[topic].size() << " bytes vs " << recorded[topic].size();
  }
}

TEST_F(SeveralLidarsCli, MistakesInPlacingTheLidarsAreOneSentenceAndUsage) {
  test::SimOnPty g6(Model::G6);
  const std::string port = "'" + g6.port() + "'";
  const std::string out = " --out '" + path("x.ydrec") + "' --seconds 1";
  const std::pair<std::string, std::string> cases[] = {
      {"record --port " + port + " --port /dev/ydscope-no-such-port" + out,
       "there is no port /dev/ydscope-no-such-port"},
      {"record --port " + port + " --pose 1,2 --port tcp://127.0.0.1:9 --pose 0,0,0" + out, "'1,2'"},
      {"record --port " + port + " --name a --port tcp://127.0.0.1:9 --name a" + out, "--name a is given to two ports"},
      {"record --port " + port + " --name 1st --port tcp://127.0.0.1:9 --name b" + out, "--name '1st'"},
      {"record --port " + port + " --port " + port + out, "is given twice"},
      {"record --port " + port + " --pose 0,0,0 --port tcp://127.0.0.1:9" + out, "once per --port (2 ports)"},
      {"record --port " + port + " --port tcp://127.0.0.1:9 --seconds 1", "say where to record"},
      {"record --port " + port + " --port tcp://127.0.0.1:9 --out '" + path("x.ydrec") + "' --mcap '" +
           path("x.ydrec") + "'",
       "must be different files"},
      {"record --port " + port + " --name front" + out, "--name and --pose"},
      // One frame for two lidars would lay their clouds on top of each other: refused, not ignored.
      {"record --port " + port + " --frame-id laser --port tcp://127.0.0.1:9" + out, "once per --port (2 ports)"},
      {"record --port " + port + " --frame-id 'front laser' --port tcp://127.0.0.1:9 --frame-id b" + out,
       "must be a ROS frame name"},
  };
  for (const auto& [arguments, says] : cases) {
    const auto run = run_cli_apart(arguments);
    EXPECT_EQ(run.status, 2) << arguments << "\n" << run.err;
    EXPECT_EQ(count(run.err, "\n"), 1u) << run.err;
    EXPECT_NE(run.err.find(says), std::string::npos) << run.err;
    EXPECT_FALSE(fs::exists(path("x.ydrec"))) << arguments;
  }
}

// A recording of several lidars writes each in a frame named after it: one --frame-id cannot name
// them, so export says so instead of dropping it; a bad --parent-frame is one sentence too.
TEST_F(SeveralLidarsCli, ExportRefusesOneFrameIdForSeveralLidarsAndABadParentFrame) {
  test::RawRecording raw(2, 16, "name=front\nmodel=G6\n");
  raw.add(RecordType::Metadata, 0,
          {'n', 'a', 'm', 'e', '=', 'b', 'a', 'c', 'k', '\n', 'm', 'o', 'd', 'e', 'l', '=', 'G', '6', '\n'}, 1);
  raw.write(path("two.ydrec"));
  const auto one_frame =
      run_cli_apart("export '" + path("two.ydrec") + "' --mcap '" + path("x.mcap") + "' --frame-id laser");
  EXPECT_EQ(one_frame.status, 2) << one_frame.err;
  EXPECT_EQ(count(one_frame.err, "\n"), 1u) << one_frame.err;
  EXPECT_NE(one_frame.err.find("holds 2 lidars"), std::string::npos) << one_frame.err;
  EXPECT_NE(one_frame.err.find("leave --frame-id out"), std::string::npos) << one_frame.err;
  const auto bad_parent =
      run_cli_apart("export '" + path("two.ydrec") + "' --mcap '" + path("x.mcap") + "' --parent-frame /base_link");
  EXPECT_EQ(bad_parent.status, 2) << bad_parent.err;
  EXPECT_NE(bad_parent.err.find("--parent-frame '/base_link' must be a ROS frame name"), std::string::npos)
      << bad_parent.err;
  EXPECT_FALSE(fs::exists(path("x.mcap")));
}

TEST_F(SeveralLidarsCli, ASourceWithoutAModelIsNamedAndNeedsModel) {
  test::RawRecording raw(2, 16, "name=front\nmodel=G6\n");
  raw.add(RecordType::Metadata, 0, {'n', 'a', 'm', 'e', '=', 'b', 'a', 'c', 'k', '\n'}, 1);
  raw.write(path("two.ydrec"));
  const auto run = run_cli_apart("decode '" + path("two.ydrec") + "'");
  EXPECT_EQ(run.status, 2);
  EXPECT_EQ(run.err, "ydscope-cli decode: " + path("two.ydrec") +
                         "'s source back does not say which lidar made it; pass --model (G1, G6, TG15, TG30, TG50)\n");
  // --model decodes every source as that model; no bytes give two empty summaries, tagged.
  const auto forced = run_cli_apart("decode '" + path("two.ydrec") + "' --model G6");
  EXPECT_EQ(forced.status, 0) << forced.err;
  EXPECT_EQ(count(forced.out, "{\"type\":\"summary\",\"source\":\"back\""), 1u) << forced.out;
  EXPECT_EQ(count(forced.out, "{\"type\":\"summary\",\"source\":\"front\""), 1u) << forced.out;
}

}  // namespace
}  // namespace ydscope
