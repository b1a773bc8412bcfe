// Issue 17: scan and record once said nothing when the lidar reported a health error (exit 0,
// empty stderr, G6 laps with "health":null though the session knew the A5 91 answer). Now a
// warning or an error is one line on stderr, once and again when it changes; laps carry the
// health the session knows; the summary carries the worst; an error makes the exit status 3.
#include <gtest/gtest.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

#include <sys/wait.h>
#include <unistd.h>

#include "cli/cli_run_support.h"
#include "support/session_test_support.h"
#include "support/temp_dir.h"
#include "support/text_file.h"

namespace ydscope {
namespace {

using test::lines_of;

using namespace test;

TEST(HealthCli, AG6HealthErrorIsOneLineTheLapsCarryItTheSummaryToo) {
  SimOnPty sim(Model::G6, [](SimServerOptions& o) { o.device.faults.health_bits = 0x12; });
  const CliResult run = run_cli_apart("scan --port " + sim.port() + " --laps 3");
  EXPECT_EQ(run.status, 3) << run.err;
  EXPECT_EQ(run.err,
            "ydscope-cli scan: health error: the lidar answered A5 91 with error (error code 0x0012); its laps may be "
            "wrong (the lidar's manual says what this means; power-cycling may clear it)\n");
  const auto lines = lines_of(run.out);
  ASSERT_EQ(lines.size(), 4u) << run.out.substr(0, 300);
  // A real G6 reports its scan rate in the zero packet's CT (the field's reading): 8 Hz as set.
  for (std::size_t i = 0; i < 3; ++i)
    EXPECT_NE(lines[i].find(R"j("scan_hz":8,"health":2,"crc_ok":null,)j"), std::string::npos)
        << lines[i].substr(lines[i].find("\"scan_hz\""), 80);
  EXPECT_NE(lines[3].find(R"j(,"health":{"level":"error","source":"A5 91","summary":"error (error code 0x0012)"}})j"),
            std::string::npos)
      << lines[3];
}

TEST(HealthCli, AHealthyLidarGivesNoLineAndExitZero) {
  SimOnPty sim(Model::TG30);
  const CliResult run = run_cli_apart("scan --port " + sim.port() + " --laps 2");
  EXPECT_EQ(run.status, 0) << run.err;
  EXPECT_EQ(run.err, "");
  EXPECT_EQ(count(run.out, R"j("health":0,)j"), 2u) << run.out.substr(0, 300);
  EXPECT_NE(run.out.find(R"j(,"health":{"level":"ok","source":"A5 91","summary":"ok"}})j"), std::string::npos);
}

TEST(HealthCli, RecordSaysItOnStderrAndInItsSummaryLine) {
  const test::TempDir dir("health-record");
  SimOnPty sim(Model::G6, [](SimServerOptions& o) { o.device.faults.health_bits = 255; });
  const std::string file = (dir / "sick.ydrec").string();
  const CliResult run = run_cli_apart("record --port " + sim.port() + " --out " + file + " --seconds 0.5");
  EXPECT_EQ(run.status, 3) << run.err;
  EXPECT_EQ(count(run.err, "\n"), 1u) << run.err;
  EXPECT_EQ(
      run.err.rfind("ydscope-cli record: health error: the lidar answered A5 91 with error (error code 0x00FF);", 0),
      0u)
      << run.err;
  EXPECT_EQ(run.out.rfind("recorded " + file + ": ", 0), 0u) << run.out;
  const std::string tail = "; the lidar reported a health error: error (error code 0x00FF) (A5 91)\n";
  ASSERT_GE(run.out.size(), tail.size());
  EXPECT_EQ(run.out.substr(run.out.size() - tail.size()), tail) << run.out;
}

// G1 reports health in every lap's CT: a change mid-scan is a new line, and so is the way back.
// The test reads the laps as they come (a pipe, as a program would) and changes the virtual
// lidar's health bits after chosen laps.
TEST(HealthCli, AG1HealthChangeMidScanIsANewLineAndSoIsTheWayBack) {
  SimOnPty sim(Model::G1);
  const test::TempDir dir("health-scan");
  const auto err_path = dir / "stderr.txt";
  const std::string command =
      std::string("'") + YDSCOPE_CLI_PATH + "' scan --port " + sim.port() + " --laps 40 2>'" + err_path.string() + "'";
  std::FILE* pipe = ::popen(command.c_str(), "r");
  ASSERT_NE(pipe, nullptr);
  std::string line;
  std::vector<std::string> laps;
  for (int c = std::fgetc(pipe); c != EOF; c = std::fgetc(pipe)) {
    if (c != '\n') {
      line.push_back(static_cast<char>(c));
      continue;
    }
    laps.push_back(line);
    line.clear();
    FaultConfig faults;
    if (laps.size() == 3) {
      faults.health_bits = kG1HealthSensor;
      sim.server().set_faults(faults);
    } else if (laps.size() == 20) {
      sim.server().set_faults(faults);  // healthy again
    }
  }
  const int status = ::pclose(pipe);
  std::ifstream err_file(err_path, std::ios::binary);
  const std::string err{std::istreambuf_iterator<char>(err_file), {}};

  EXPECT_EQ(WEXITSTATUS(status), 3) << err;
  const auto err_lines = lines_of(err);
  ASSERT_EQ(err_lines.size(), 2u) << err;
  EXPECT_NE(err_lines[0].find("ydscope-cli scan: health error: lap "), std::string::npos) << err_lines[0];
  EXPECT_NE(err_lines[0].find("'s CT health says abnormal: sensor; its laps may be wrong"), std::string::npos)
      << err_lines[0];
  EXPECT_NE(err_lines[1].find("ydscope-cli scan: health ok again: lap "), std::string::npos) << err_lines[1];
  EXPECT_NE(err_lines[1].find("'s CT health says ok"), std::string::npos) << err_lines[1];
  ASSERT_EQ(laps.size(), 41u);
  EXPECT_EQ(count(laps.back(), R"j("health":{"level":"error","source":"CT","summary":"abnormal: sensor"})j"), 1u)
      << laps.back();
  std::size_t sick_laps = 0;
  for (const std::string& lap : laps) sick_laps += count(lap, R"j("health":1,)j");
  EXPECT_GT(sick_laps, 0u) << "no lap carried the sensor bit";
}

}  // namespace
}  // namespace ydscope
