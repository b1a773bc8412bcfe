// `ydscope-cli decode` as a user runs it: output format, counts on real captures, exit codes.
#include <gtest/gtest.h>
#include <unistd.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "core/protocol/lap.h"
#include "core/protocol/reply.h"
#include "cli/cli_run_support.h"
#include "core/protocol_test_support.h"
#include "support/temp_dir.h"

namespace ydscope {
namespace {

using test::append;
using test::Bytes;

using test::run_cli_apart;

// Files the tests write, gone when the suite ends.
const test::TempDir& scratch() {
  static const test::TempDir dir("cli-decode");
  return dir;
}

std::string capture_arg(const std::string& name) { return "'" + test::capture(name).string() + "'"; }

std::vector<std::string> lines(const std::string& text) {
  std::vector<std::string> out;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) out.push_back(line);
  return out;
}

std::string write_temp(const std::string& name, const Bytes& bytes) {
  const std::string path = scratch().file(name);
  std::ofstream(path, std::ios::binary)
      .write(reinterpret_cast<const char*>(bytes.data()), static_cast<std::streamsize>(bytes.size()));
  return path;
}

TEST(CliDecode, SummaryOfRealCaptures) {
  auto run = run_cli_apart("decode --model G6 --format summary " + capture_arg("x4-scan1.bin"));
  EXPECT_EQ(run.status, 0) << run.err;
  EXPECT_EQ(run.out, R"({"type":"summary","bytes":38074,"packets":455,"checksum_errors":0,"zero_packets":28,"laps":27})"
                     "\n");
  run = run_cli_apart("decode --model g6 --format summary " + capture_arg("x4class-with-bad-checksum.bin"));
  EXPECT_EQ(run.status, 0) << run.err;
  EXPECT_EQ(run.out, R"({"type":"summary","bytes":244,"packets":2,"checksum_errors":1,"zero_packets":1,"laps":0})"
                     "\n");
}

TEST(CliDecode, JsonlLapsThenSummary) {
  const auto run = run_cli_apart("decode --model G6 " + capture_arg("x4-scan1.bin"));
  ASSERT_EQ(run.status, 0) << run.err;
  const auto all = lines(run.out);
  ASSERT_EQ(all.size(), 28u);  // 27 laps + summary
  for (std::size_t i = 0; i < 27; ++i) {
    EXPECT_EQ(all[i].rfind(R"({"type":"lap","index":)" + std::to_string(i) + R"(,"t":)", 0), 0u)
        << all[i].substr(0, 60);
    EXPECT_NE(all[i].find(R"(,"points":[[)"), std::string::npos) << all[i].substr(0, 60);
    EXPECT_NE(all[i].find(R"(],"scan_hz":null,"health":null,"crc_ok":null,"packets":)"), std::string::npos);
    EXPECT_EQ(all[i].back(), '}');
  }
  // Lap 0: 19 packets, 601 points (walked independently), no checksum errors.
  const std::string& lap0 = all[0];
  EXPECT_NE(lap0.find(R"("packets":19,"checksum_errors":0})"), std::string::npos);
  std::size_t points = 0;
  for (std::size_t at = lap0.find("[["); at != std::string::npos; at = lap0.find("],[", at + 1)) ++points;
  EXPECT_EQ(points, 601u);
  // The first point: the zero packet at 348.515625 deg (0x5731 raw), range 0 -> no correction.
  EXPECT_EQ(lap0.find(R"("points":[[348.5156,0,0],)"), lap0.find(R"("points")"));
  EXPECT_EQ(all[27].rfind(R"({"type":"summary")", 0), 0u);
}

TEST(CliDecode, StdinGivesTheSameOutput) {
  const auto from_file = run_cli_apart("decode --model G6 " + capture_arg("x4-scan2.bin"));
  const auto from_stdin = run_cli_apart("decode --model G6 - < " + capture_arg("x4-scan2.bin"));
  EXPECT_EQ(from_stdin.status, 0) << from_stdin.err;
  EXPECT_EQ(from_file.out, from_stdin.out);
}

TEST(CliDecode, G1CtInformationCrcAndFilters) {
  test::G1LapSpec spec;
  spec.scan_hz = 9.6;
  spec.health = kG1HealthData;
  spec.packets = 4;
  spec.lsn = 2;
  Bytes stream;
  std::uint8_t crc = test::append_g1_lap(stream, spec, 0x00);
  crc = test::append_g1_lap(stream, spec, crc);
  // Points with each flag, in a lap of their own: 1000 mm as G1 sample words.
  stream.push_back(crc);
  const std::vector<std::uint8_t> cts{g1_zero_packet_ct(9.6), 0x00};
  append(stream, test::packet(cts[0], 0.0, 0.0, {1000 << 2}));
  append(stream,
         test::packet(cts[1], 90.0, 93.0, {(1000 << 2) | 1, (1000 << 2) | 2, (1000 << 2) | 3, (1000 << 2) | 2}));
  stream.push_back(ct_crc8(cts));
  append(stream, test::packet(cts[0], 0.0, 0.0, {1000 << 2}));
  const std::string path = write_temp("g1.bin", stream);

  auto run = run_cli_apart("decode --model G1 '" + path + "'");
  ASSERT_EQ(run.status, 0) << run.err;
  auto all = lines(run.out);
  ASSERT_EQ(all.size(), 4u);
  EXPECT_NE(all[0].find(R"("scan_hz":9.6,"health":32,"crc_ok":true,"packets":5,"checksum_errors":0})"),
            std::string::npos)
      << all[0];
  // Lap 2 is too short to carry a health packet; its CRC matches.
  EXPECT_NE(all[2].find(R"("scan_hz":9.6,"health":null,"crc_ok":true,"packets":2,)"), std::string::npos) << all[2];
  EXPECT_NE(all[2].find(R"(,1000,1],)"), std::string::npos);
  EXPECT_NE(all[2].find(R"(,1000,2],)"), std::string::npos);
  EXPECT_EQ(all[3], R"({"type":"summary","bytes":)" + std::to_string(stream.size()) +
                        R"(,"packets":13,"checksum_errors":0,"zero_packets":4,"laps":3})");  // 2*(1+4) + 2 + 1

  run = run_cli_apart("decode --model G1 --filter specular '" + path + "'");
  all = lines(run.out);
  ASSERT_EQ(all.size(), 4u);
  EXPECT_EQ(all[2].find(",1000,2]"), std::string::npos);
  EXPECT_NE(all[2].find(",1000,3]"), std::string::npos);
  run = run_cli_apart("decode --model G1 --filter specular,ambient '" + path + "'");
  all = lines(run.out);
  ASSERT_EQ(all.size(), 4u);
  EXPECT_EQ(all[2].find(",1000,3]"), std::string::npos);
  EXPECT_NE(all[2].find(",1000,1]"), std::string::npos);  // flag 1 is not interference
}

TEST(CliDecode, CrcMismatchNullsTheCtInformation) {
  test::G1LapSpec spec;
  Bytes stream;
  const std::uint8_t crc = test::append_g1_lap(stream, spec, 0x00);
  test::append_g1_lap(stream, spec, static_cast<std::uint8_t>(crc + 1));
  const std::string path = write_temp("g1bad.bin", stream);
  const auto run = run_cli_apart("decode --model G1 '" + path + "'");
  ASSERT_EQ(run.status, 0) << run.err;
  EXPECT_NE(run.out.find(R"("scan_hz":null,"health":null,"crc_ok":false,)"), std::string::npos) << run.out;
}

// Issue 17: with no LastCRC byte before the closing zero packet, crc_ok was false; it is unknown.
TEST(CliDecode, MissingLastCrcIsNullNotFalse) {
  test::G1LapSpec spec;
  Bytes stream;
  test::append_g1_lap(stream, spec, 0x00);
  Bytes next;
  test::append_g1_lap(next, spec, 0x00);
  append(stream, Bytes(next.begin() + 1, next.end()));  // no byte between the last packet and the zero packet
  test::append_g1_lap(stream, spec, 0x00);
  const std::string path = write_temp("g1nocrc.bin", stream);
  const auto run = run_cli_apart("decode --model G1 '" + path + "'");
  ASSERT_EQ(run.status, 0) << run.err;
  const auto all = lines(run.out);
  ASSERT_EQ(all.size(), 3u);
  EXPECT_NE(all[0].find(R"("scan_hz":9,"health":0,"crc_ok":null,)"), std::string::npos) << all[0];
  EXPECT_NE(all[1].find(R"("crc_ok":true,)"), std::string::npos) << all[1];
}

// Issue 17: 110 packets of 255 samples came out as 24000 points without a word.
TEST(CliDecode, AnOverlongLapSaysHowManyPointsWereCut) {
  Bytes stream = test::packet(kCtLapStart, 0.0, 0.0, {40});
  for (int i = 0; i < 110; ++i) append(stream, test::packet(0, 10.0, 20.0, std::vector<std::uint16_t>(255, 400)));
  append(stream, test::packet(kCtLapStart, 0.0, 0.0, {40}));
  const std::string path = write_temp("long.bin", stream);
  const auto run = run_cli_apart("decode --model G6 '" + path + "'");
  ASSERT_EQ(run.status, 0) << run.err;
  const auto all = lines(run.out);
  ASSERT_EQ(all.size(), 2u);
  const std::size_t cut = 1 + 110 * 255 - Lap::kMaxPoints;  // 4051
  EXPECT_NE(all[0].find(R"("packets":111,"checksum_errors":0,"cut_points":)" + std::to_string(cut) + "}"),
            std::string::npos)
      << all[0].substr(all[0].size() - 120);
  EXPECT_NE(all[1].find(R"("laps":1,"cut_points":)" + std::to_string(cut) + "}"), std::string::npos) << all[1];
}

TEST(CliDecode, DistanceScaleOverride) {
  Bytes stream = test::packet(kCtLapStart, 0.0, 0.0, {0});
  append(stream, test::packet(0, 100.0, 100.0, {0x6FE5}));
  append(stream, test::packet(kCtLapStart, 0.0, 0.0, {0}));
  const std::string path = write_temp("scale.bin", stream);
  // Raw bytes are read as real units write them: a TG on current firmware in mm, a G6 at S/2.
  auto run = run_cli_apart("decode --model TG30 '" + path + "'");
  EXPECT_NE(run.out.find(",28645,0]"), std::string::npos) << run.out;
  run = run_cli_apart("decode --model G6 '" + path + "'");
  EXPECT_NE(run.out.find(",14322.5,0]"), std::string::npos) << run.out;
  // The manuals' reading: the TG manual's worked example, 0x6FE5 -> 14322.50 mm.
  run = run_cli_apart("decode --model TG30 --conventions manual '" + path + "'");
  EXPECT_NE(run.out.find(",14322.5,0]"), std::string::npos) << run.out;
  run = run_cli_apart("decode --model G6 --conventions manual '" + path + "'");
  EXPECT_NE(run.out.find(",7161.25,0]"), std::string::npos) << run.out;
  run = run_cli_apart("decode --model TG30 --distance-scale 0.5 '" + path + "'");
  EXPECT_NE(run.out.find(",14322.5,0]"), std::string::npos) << run.out;
  run = run_cli_apart("decode --model TG30 --conventions paper '" + path + "'");
  EXPECT_EQ(run.status, 2);
  EXPECT_NE(run.err.find("unknown --conventions 'paper'"), std::string::npos) << run.err;
}

TEST(CliDecode, X4BytesDecodeAsAnX4ThoughNoCommandDrivesOne) {
  const auto run = run_cli_apart("decode --model x4 --format summary " + capture_arg("x4-scan1.bin"));
  EXPECT_EQ(run.status, 0) << run.err;
  EXPECT_NE(run.out.find(R"("packets":455,"checksum_errors":0,"zero_packets":28,"laps":27)"), std::string::npos)
      << run.out;
  const auto scan = run_cli_apart("scan --port /dev/null --model X4 --laps 1");
  EXPECT_EQ(scan.status, 2) << "ydscope drives G1, G6 and TG only";
  EXPECT_NE(scan.err.find("unknown model 'X4'"), std::string::npos) << scan.err;
}

TEST(CliDecode, UsageErrorsExitTwoWithOneSentence) {
  auto run = run_cli_apart("decode --model X9 " + capture_arg("x4-scan1.bin"));
  EXPECT_EQ(run.status, 2);
  EXPECT_TRUE(run.out.empty());
  EXPECT_NE(run.err.find("unknown model 'X9'"), std::string::npos) << run.err;
  EXPECT_NE(run.err.find("G1, G6, TG15, TG30, TG50"), std::string::npos) << run.err;

  run = run_cli_apart("decode --model G6 /nonexistent/scan.bin");
  EXPECT_EQ(run.status, 2);
  EXPECT_NE(run.err.find("'/nonexistent/scan.bin' was not found"), std::string::npos) << run.err;

  run = run_cli_apart("decode " + capture_arg("x4-scan1.bin"));
  EXPECT_EQ(run.status, 2);
  EXPECT_NE(run.err.find("--model"), std::string::npos) << run.err;

  run = run_cli_apart("decode --model G6 --format xml " + capture_arg("x4-scan1.bin"));
  EXPECT_EQ(run.status, 2);
  run = run_cli_apart("decode --model G6 --filter glare " + capture_arg("x4-scan1.bin"));
  EXPECT_EQ(run.status, 2);
  run = run_cli_apart("decode --model G6 --distance-scale -1 " + capture_arg("x4-scan1.bin"));
  EXPECT_EQ(run.status, 2);
  run = run_cli_apart("decode --model G6");
  EXPECT_EQ(run.status, 2);
  EXPECT_EQ(std::count(run.err.begin(), run.err.end(), '\n'), 1);
}

TEST(CliDecode, ReadErrorExitsOne) {
  const auto run = run_cli_apart("decode --model G6 '" + std::filesystem::temp_directory_path().string() + "'");
  EXPECT_EQ(run.status, 1);
  EXPECT_FALSE(run.err.empty());
}

TEST(CliDecode, HelpExplainsTheSchema) {
  const auto run = run_cli_apart("decode --help");
  EXPECT_EQ(run.status, 0);
  for (const char* needle : {"--model", "--format", "--filter", "--distance-scale", R"("type":"lap")",
                             R"("type":"summary")", "crc_ok", "exit status"})
    EXPECT_NE(run.out.find(needle), std::string::npos) << needle;
}

}  // namespace
}  // namespace ydscope
