// How decode, replay and scan print laps: each lap's time `t` (from the recorded receive times, so
// decode and replay at any speed agree; from live ones in scan), the summary's wall-clock "start",
// and --format csv.
#include <gtest/gtest.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

#include "cli/cli_run_support.h"
#include "core/protocol_test_support.h"
#include "core/record/recording_writer.h"
#include "support/session_test_support.h"
#include "support/temp_dir.h"
#include "support/text_file.h"

namespace ydscope {
namespace {

using test::lines_of;

using test::CliResult;
using test::run_cli_apart;

class LapOutputCli : public ::testing::Test {
 protected:
  std::string path(const char* name) const { return dir_.file(name); }

  // A G6 recording of `laps` laps whose record k (zero packet k and the rest of lap k) was
  // received at k * 100 ms: lap k is closed by the zero packet of record k + 1.
  std::string write_recording(int laps) {
    const std::string file = path("timed.ydrec");
    RecordingMetadata metadata;
    metadata.model = "G6";
    metadata.start_wall_time = "2026-12-02T05:00:00.000Z";
    std::string error;
    auto writer = RecordingWriter::create(file, metadata, 0, error);
    EXPECT_TRUE(writer) << error;
    if (!writer) return file;
    std::uint16_t value = 4000;
    for (int k = 0; k <= laps; ++k) {
      test::Bytes record = test::packet(kCtLapStart, 0.0, 0.0, {0});
      for (int i = 0; k < laps && i < 12; ++i) {
        std::vector<std::uint16_t> samples(20);
        for (auto& s : samples) s = value = static_cast<std::uint16_t>(value * 31 + 7);
        test::append(record, test::packet(0, i * 30.0 + 0.2, i * 30.0 + 29.6, samples));
      }
      EXPECT_TRUE(writer->append(Direction::DeviceToHost, record, std::int64_t{k} * 100'000'000));
    }
    return file;
  }

  test::TempDir dir_{"lap-output-cli"};
};

// The "t" of every lap line, in order.
std::vector<double> lap_times(const std::string& jsonl) {
  std::vector<double> times;
  static const std::regex t(R"re(^\{"type":"lap","index":\d+,"t":([0-9.]+),"points")re");
  for (const std::string& line : lines_of(jsonl)) {
    std::smatch m;
    if (std::regex_search(line, m, t)) times.push_back(std::strtod(m[1].str().c_str(), nullptr));
  }
  return times;
}

TEST_F(LapOutputCli, LapTimesAreTheRecordedReceiveTimesAndEverySpeedPrintsTheSame) {
  const std::string file = write_recording(4);
  const CliResult decoded = run_cli_apart("decode '" + file + "'");
  ASSERT_EQ(decoded.status, 0) << decoded.err;
  const std::vector<double> times = lap_times(decoded.out);
  ASSERT_EQ(times.size(), 4u) << decoded.out.substr(0, 300);
  for (std::size_t k = 0; k < times.size(); ++k)
    EXPECT_DOUBLE_EQ(times[k], 0.1 * static_cast<double>(k + 1)) << "lap " << k << " closes in record " << k + 1;
  EXPECT_NE(decoded.out.find(R"(,"start":"2026-12-02T05:00:00.000Z"})"), std::string::npos) << decoded.out;

  for (const char* speed : {"0", "1", "3"}) {
    const CliResult replayed = run_cli_apart("replay '" + file + "' --speed " + speed);
    ASSERT_EQ(replayed.status, 0) << replayed.err;
    EXPECT_EQ(replayed.out, decoded.out) << "--speed " << speed;
  }
}

TEST_F(LapOutputCli, CsvHasAHeaderAndOneRowPerPointWithTheJsonValues) {
  const std::string file = write_recording(3);
  const CliResult json = run_cli_apart("decode '" + file + "'");
  const CliResult csv = run_cli_apart("decode --format csv '" + file + "'");
  ASSERT_EQ(csv.status, 0) << csv.err;
  const std::vector<std::string> rows = lines_of(csv.out);
  ASSERT_FALSE(rows.empty());
  EXPECT_EQ(rows[0], "lap,t,angle_deg,range_mm,flag");
  // Rebuild each lap's JSON points from the rows: they must be the decode's, value for value.
  std::vector<std::string> points(3);
  std::vector<std::string> times(3);
  for (std::size_t r = 1; r < rows.size(); ++r) {
    std::istringstream row(rows[r]);
    std::string lap, t, angle, range, flag;
    ASSERT_TRUE(std::getline(row, lap, ',') && std::getline(row, t, ',') && std::getline(row, angle, ',') &&
                std::getline(row, range, ',') && std::getline(row, flag))
        << rows[r];
    const std::size_t index = std::stoul(lap);
    ASSERT_LT(index, points.size()) << rows[r];
    points[index] += (points[index].empty() ? "[" : ",[") + angle + "," + range + "," + flag + "]";
    times[index] = t;
  }
  const std::vector<std::string> json_lines = lines_of(json.out);
  ASSERT_EQ(json_lines.size(), 4u);  // three laps and the summary
  for (std::size_t k = 0; k < 3; ++k) {
    EXPECT_NE(json_lines[k].find("\"t\":" + times[k] + ",\"points\":[" + points[k] + "]"), std::string::npos)
        << "lap " << k;
  }
  EXPECT_EQ(csv.out.find("summary"), std::string::npos) << "a CSV holds only its rows";
  const CliResult replayed = run_cli_apart("replay --format csv --speed 0 '" + file + "'");
  EXPECT_EQ(replayed.out, csv.out);
}

TEST_F(LapOutputCli, ARawCaptureIsTimedAtTheModelsBaudRate) {
  const std::string capture = "'" + test::capture("x4-scan1.bin").string() + "'";
  const CliResult decoded = run_cli_apart("decode --model G6 " + capture);
  ASSERT_EQ(decoded.status, 0) << decoded.err;
  const std::vector<double> times = lap_times(decoded.out);
  ASSERT_EQ(times.size(), 27u);
  for (std::size_t k = 1; k < times.size(); ++k) EXPECT_GT(times[k], times[k - 1]) << "lap " << k;
  // 38 074 bytes at 512 000 baud, ten bits a byte, take 0.7436 s: no lap can close later.
  EXPECT_GT(times.front(), 0.0);
  EXPECT_LE(times.back(), 38074 * 10.0 / 512000.0);
  EXPECT_EQ(decoded.out.find("\"start\""), std::string::npos) << "raw bytes have no wall-clock start";
}

TEST_F(LapOutputCli, ScanStampsLapsWithReceiveTimesAndTheSummaryWithTheStart) {
  test::SimOnPty sim(Model::G6);
  const CliResult scan = run_cli_apart("scan --port " + sim.port() + " --laps 4");
  ASSERT_EQ(scan.status, 0) << scan.err;
  const std::vector<double> times = lap_times(scan.out);
  ASSERT_EQ(times.size(), 4u) << scan.out.substr(0, 300);
  EXPECT_GT(times[0], 0.0);
  for (std::size_t k = 1; k < times.size(); ++k) EXPECT_GT(times[k], times[k - 1]) << "lap " << k;
  EXPECT_TRUE(std::regex_search(scan.out, std::regex(R"re("start":"20\d\d-\d\d-\d\dT\d\d:\d\d:\d\d\.\d{3}Z")re")))
      << lines_of(scan.out).back();

  const CliResult csv = run_cli_apart("scan --port " + sim.port() + " --laps 2 --format csv");
  ASSERT_EQ(csv.status, 0) << csv.err;
  EXPECT_EQ(csv.out.rfind("lap,t,angle_deg,range_mm,flag\n", 0), 0u);
  EXPECT_GT(lines_of(csv.out).size(), 100u);  // two G6 laps are over a thousand points
}

TEST_F(LapOutputCli, AnUnknownFormatNamesTheThreeThatExist) {
  const std::string file = write_recording(1);
  for (const std::string& command :
       std::vector<std::string>{"decode --model G6 -", "replay '" + file + "'", "scan --port /dev/null --laps 1"}) {
    const CliResult run = run_cli_apart(command + " --format xml < /dev/null");
    EXPECT_EQ(run.status, 2) << command;
    EXPECT_NE(run.err.find("--format must be jsonl, csv or summary, not 'xml'"), std::string::npos)
        << command << ": " << run.err;
  }
}

}  // namespace
}  // namespace ydscope
