// ydscope-cli check with two --port: two virtual lidars checked at once over one run, one healthy
// and one whose motor runs slow, so each unit gets its own verdict and its own report, and the set
// fails because one unit does.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>

#include "cli/cli_run_support.h"
#include "support/session_test_support.h"
#include "support/temp_dir.h"
#include "support/text_file.h"

namespace ydscope {
namespace {

using test::read_text;

using namespace test;

constexpr const char* kGood = "00000000000000AA";
constexpr const char* kSlow = "00000000000000BB";

// The report in `folder` whose name begins with `serial` (SERIAL-YYYYMMDD-HHMMSS.html); empty if none.
std::string report_of(const TempDir& folder, const std::string& serial) {
  for (const auto& entry : std::filesystem::directory_iterator(folder.path()))
    if (entry.path().filename().string().rfind(serial + "-", 0) == 0 && entry.path().extension() == ".html")
      return read_text(entry.path());
  return {};
}

class CheckSetCli : public ::testing::Test {
 protected:
  // Two G6, told apart by serial; the second turns 0.6 Hz slower than it is set to.
  SimOnPty good_{Model::G6, [](SimServerOptions& o) { o.device.serial = kGood; }};
  SimOnPty slow_{Model::G6, [](SimServerOptions& o) {
                   o.device.serial = kSlow;
                   o.device.faults.scan_hz_offset = -0.6;
                 }};
  // At the units' own baud, as check_cli_test.cpp's check() explains.
  std::string ports() { return " --port " + good_.port() + " --port " + slow_.port() + " --baud 512000"; }
};

TEST_F(CheckSetCli, EachUnitHasItsVerdictAndItsReportAndTheSetFailsWithTheSlowOne) {
  TempDir reports("check-set");
  const CliResult run = run_cli_apart(
      "check" + ports() + " --name front --name rear --seconds 2 --settle-seconds 0.3 --reports " + reports.string());
  EXPECT_EQ(run.status, 3) << run.out << run.err;
  const std::size_t front = run.out.find("front (" + good_.port() + "):\n");
  const std::size_t rear = run.out.find("rear (" + slow_.port() + "):\n");
  ASSERT_NE(front, std::string::npos) << run.out;
  ASSERT_NE(rear, std::string::npos) << run.out;
  ASSERT_LT(front, rear) << "in --port order";
  // Each unit's lines are a lone check's, under its name.
  const std::string front_part = run.out.substr(front, rear - front);
  const std::string rear_part = run.out.substr(rear);
  EXPECT_NE(front_part.find(std::string("serial ") + kGood), std::string::npos) << front_part;
  EXPECT_NE(front_part.find("verdict: PASS (8 criteria)"), std::string::npos) << front_part;
  EXPECT_NE(rear_part.find(std::string("serial ") + kSlow), std::string::npos) << rear_part;
  EXPECT_NE(rear_part.find("FAIL  scan rate"), std::string::npos) << rear_part;
  EXPECT_NE(rear_part.find("verdict: FAIL (1 of 8 criteria: scan_rate)"), std::string::npos) << rear_part;
  EXPECT_NE(run.out.find(std::string("lidars: front PASS (G6 ") + kGood + "), rear FAIL (G6 " + kSlow + ")\n"),
            std::string::npos)
      << run.out;
  EXPECT_NE(run.out.find("overall: FAIL (2 lidars; failed: rear)\n"), std::string::npos) << run.out;

  // One report per unit, named by its serial, each with that unit's verdict.
  const std::string good_html = report_of(reports, kGood);
  const std::string slow_html = report_of(reports, kSlow);
  ASSERT_FALSE(good_html.empty()) << "no report named " << kGood << "-... in " << reports.string();
  ASSERT_FALSE(slow_html.empty()) << "no report named " << kSlow << "-... in " << reports.string();
  EXPECT_NE(good_html.find(R"(<span class="verdict pass" id="verdict">PASS</span>)"), std::string::npos);
  EXPECT_NE(slow_html.find(R"(<span class="verdict fail" id="verdict">FAIL</span>)"), std::string::npos);
  EXPECT_NE(slow_html.find(kSlow), std::string::npos);
  EXPECT_EQ(good_html.find(kSlow), std::string::npos) << "each report holds its own unit only";
  EXPECT_NE(run.out.find("report: " + reports.string()), std::string::npos) << run.out;
}

TEST_F(CheckSetCli, TheJsonHoldsEachUnitsCheckAndTheSetsVerdict) {
  const CliResult run = run_cli_apart("check" + ports() + " --seconds 1 --settle-seconds 0.3 --format json");
  EXPECT_EQ(run.status, 3) << run.out << run.err;
  EXPECT_EQ(run.out.rfind(R"({"type":"check_set","verdict":"fail","failed":["lidar1"],"incomplete":[],"units":[)", 0),
            0u)
      << run.out;
  EXPECT_NE(run.out.find(R"({"name":"lidar0","port":")" + good_.port() +
                         R"(","verdict":"pass","report":null,"failure":null,"check":{"type":"check","verdict":"pass")"),
            std::string::npos)
      << run.out;
  EXPECT_NE(
      run.out.find(
          R"({"name":"lidar1","port":")" + slow_.port() +
          R"(","verdict":"fail","report":null,"failure":null,"check":{"type":"check","verdict":"fail","failed":["scan_rate"])"),
      std::string::npos)
      << run.out;
  EXPECT_EQ(count(run.out, "\n"), 1u) << "one object";
}

TEST(CheckSetCliMistakes, OneReportFileOrALoopOfSeveralIsAUsageError) {
  SimOnPty a(Model::G6);
  SimOnPty b(Model::G6);
  const std::string two = " --port " + a.port() + " --port " + b.port();
  for (const std::string& args : {"check" + two + " --report unit.html", "check --loop --station s --operator o" + two,
                                  "check" + two + " --reports /nonexistent-folder"}) {
    const CliResult run = run_cli(args);
    EXPECT_EQ(run.status, 2) << args << "\n" << run.out;
    EXPECT_NE(run.out.find("ydscope-cli check: "), std::string::npos) << args << "\n" << run.out;
  }
}

}  // namespace
}  // namespace ydscope
