// ydscope-cli check against the virtual lidar of each model: a healthy unit passes, and each fault
// the virtual lidar can inject fails exactly the criterion it breaks, by name.
#include <gtest/gtest.h>

#include <csignal>
#include <filesystem>
#include <fstream>
#include <future>
#include <string>
#include <thread>
#include <unistd.h>

#include "cli/cli_run_support.h"
#include "support/session_test_support.h"
#include "support/text_file.h"

namespace ydscope {
namespace {

using test::read_text;

using namespace test;

// Short runs keep the suite quick; the settle time covers the restart after setting the rate.
const std::string kQuick = " --seconds 2 --settle-seconds 0.3 --format json";

// The ids in the JSON verdict's "failed" list, e.g. "link" or "health,link".
std::string failed_ids(const std::string& json) {
  const auto at = json.find("\"failed\":[");
  if (at == std::string::npos) return "<no verdict>";
  const auto begin = at + 10, end = json.find(']', begin);
  std::string ids;
  for (char c : json.substr(begin, end - begin))
    if (c != '"') ids += c;
  return ids;
}

// At the unit's own baud, where a real unit answers: a pseudo-terminal passes bytes whatever the
// baud, so the model-detecting probe would otherwise settle at 230400 with a G6 or TG streaming at
// twice what that baud carries, and the measured lap times come out several per cent fast (open:
// the virtual lidar should garble at a wrong baud as a real line does, tests/link/wrong_baud_test).
CliResult check(SimOnPty& sim, const std::string& more = "") {
  std::uint32_t baud = 0;
  sim.server().with_device([&](VirtualLidar& d) { baud = d.profile().default_baud; });
  return run_cli_apart("check --port " + sim.port() + " --baud " + std::to_string(baud) + kQuick + more);
}

class CheckEveryModel : public ::testing::TestWithParam<Model> {};

TEST_P(CheckEveryModel, AHealthyVirtualLidarPasses) {
  SimOnPty sim(GetParam());
  const CliResult run = check(sim);
  EXPECT_EQ(run.status, 0) << run.out;
  EXPECT_NE(run.out.find("\"verdict\":\"pass\""), std::string::npos) << run.out;
  EXPECT_EQ(failed_ids(run.out), "") << run.out;
  EXPECT_NE(run.out.find("\"model\":\"" + std::string(profile_for(GetParam()).name) + "\""), std::string::npos);
  DeviceMode mode = DeviceMode::Scanning;
  sim.server().with_device([&](VirtualLidar& d) { mode = d.mode(); });
  EXPECT_EQ(mode, DeviceMode::Idle) << "check leaves the motor stopped";
}

INSTANTIATE_TEST_SUITE_P(Models, CheckEveryModel,
                         ::testing::Values(Model::G1, Model::G6, Model::TG15, Model::TG30, Model::TG50),
                         [](const auto& model) { return std::string(profile_for(model.param).name); });

// Real units win (docs/conventions.md): a unit is judged against what a real unit of its model
// and firmware emits, and the conventions used are named in the verdict.
class CheckRealUnit : public ::testing::TestWithParam<Model> {};

TEST_P(CheckRealUnit, AUnitEmittingTheFieldsRatesPassesUnderTheFieldsConventions) {
  SimOnPty sim(GetParam());  // the virtual lidar imitates real units by default
  const CliResult run = check(sim);
  EXPECT_EQ(run.status, 0) << run.out;
  const ModelProfile& profile = profile_for(GetParam());
  const UnitConventions& field = conventions_for(profile, std::nullopt, Reading::Field);
  EXPECT_NE(run.out.find("\"conventions\":{\"id\":\"" + std::string(field.id) + "\""), std::string::npos) << run.out;
  const double rate = *field.samples_per_s(profile, profile.default_ranging_khz);
  EXPECT_NE(run.out.find(std::to_string(static_cast<int>(rate)) + " samples/s"), std::string::npos)
      << "the limit names the rate: " << run.out;
  // Its own report of the scan rate, read with the right formula (TG: CT[7:1] / 10 + 3 Hz).
  const std::string reported = GetParam() == Model::G6 ? "8.00" : "10.00";
  EXPECT_NE(run.out.find("the unit reports " + reported + " Hz"), std::string::npos) << run.out;
}

TEST_P(CheckRealUnit, AUnitEmittingTheManualsRatesFailsTheSampleRateOnly) {
  // Half the samples a real unit sends: what a unit built to the manual's table would emit.
  SimOnPty sim(GetParam(), [](SimServerOptions& o) { o.device.reading = Reading::Manual; });
  const double manual_scale = conventions_for(profile_for(GetParam()), std::nullopt, Reading::Manual).distance_scale;
  const CliResult run = check(sim, " --distance-scale " + std::to_string(manual_scale));
  EXPECT_EQ(run.status, 3) << run.out;
  EXPECT_EQ(failed_ids(run.out), "sample_rate") << run.out;
}

TEST_P(CheckRealUnit, TheManualsReadingOfAManualUnitPasses) {
  SimOnPty sim(GetParam(), [](SimServerOptions& o) { o.device.reading = Reading::Manual; });
  const CliResult run = check(sim, " --conventions manual");
  EXPECT_EQ(run.status, 0) << run.out;
  EXPECT_EQ(failed_ids(run.out), "") << run.out;
  EXPECT_NE(run.out.find("\"reading\":\"manual\""), std::string::npos) << run.out;
}

INSTANTIATE_TEST_SUITE_P(Models, CheckRealUnit, ::testing::Values(Model::G6, Model::TG30),
                         [](const auto& model) { return std::string(profile_for(model.param).name); });

struct CheckFaultCase {
  const char* name;
  Model model;
  std::function<void(FaultConfig&)> inject;
  const char* fails;  // the one criterion id it must fail
};

class CheckFault : public ::testing::TestWithParam<CheckFaultCase> {};

TEST_P(CheckFault, FailsExactlyTheCriterionItBreaks) {
  const CheckFaultCase& c = GetParam();
  SimOnPty sim(c.model, [&](SimServerOptions& o) { c.inject(o.device.faults); });
  const CliResult run = check(sim);
  EXPECT_EQ(run.status, 3) << run.out << run.err;
  EXPECT_EQ(failed_ids(run.out), c.fails) << run.out << run.err;
}

const CheckFaultCase kFaults[] = {
    {"Corruption", Model::G6, [](FaultConfig& f) { f.corrupt_byte_rate = 0.0005; }, "link"},
    {"LostPackets", Model::TG30, [](FaultConfig& f) { f.lost_packet_rate = 0.01; }, "link"},
    {"LostPacketsG1", Model::G1, [](FaultConfig& f) { f.lost_packet_rate = 0.01; }, "link"},
    {"HealthError", Model::G6, [](FaultConfig& f) { f.health_bits = 0x04; }, "health"},
    {"HealthBitsG1", Model::G1, [](FaultConfig& f) { f.health_bits = 0x02; }, "health"},
    // A stall is covered by LapTiming.AStallIsAnInterruptionNotJitter on the simulated clock; on
    // a pty under heavy load it also moved the scan rate now and then, so it is not here yet.
    {"ScanRateOffItsSetValue", Model::G6, [](FaultConfig& f) { f.scan_hz_offset = 0.5; }, "scan_rate"},
    {"ScanRateWandering", Model::TG15, [](FaultConfig& f) { f.scan_hz_wobble = 0.4; }, "scan_jitter"},
    {"BlockedSector", Model::G6,
     [](FaultConfig& f) {
       f.blocked_from_deg = 40;
       f.blocked_width_deg = 35;
     },
     "blockage"},
};

INSTANTIATE_TEST_SUITE_P(Faults, CheckFault, ::testing::ValuesIn(kFaults),
                         [](const auto& fault) { return std::string(fault.param.name); });

TEST(CheckCli, TheTextVerdictNamesTheFailedCriterion) {
  SimOnPty sim(Model::G6, [](SimServerOptions& o) { o.device.faults.scan_hz_offset = -0.6; });
  // At the unit's own baud, as check() explains.
  const CliResult run = run_cli_apart("check --port " + sim.port() + " --baud 512000 --seconds 2 --settle-seconds 0.3");
  EXPECT_EQ(run.status, 3) << run.out;
  EXPECT_NE(run.out.find("FAIL  scan rate"), std::string::npos) << run.out;
  EXPECT_NE(run.out.find("PASS  sample rate"), std::string::npos) << run.out;
  EXPECT_NE(run.out.find("verdict: FAIL (1 of 8 criteria: scan_rate)"), std::string::npos) << run.out;
}

// Issue 29: a sector the virtual lidar blocks (40°–75°) fails "blocked sectors" with its angles,
// within a few degrees, in the text, the JSON and the report alike.
TEST(CheckCli, ABlockedSectorIsNamedWithItsAnglesInEveryFormat) {
  SimOnPty sim(Model::G6, [](SimServerOptions& o) {
    o.device.scene = "room";
    o.device.faults.blocked_from_deg = 40;
    o.device.faults.blocked_width_deg = 35;
  });
  const std::filesystem::path report = std::filesystem::temp_directory_path() / "ydscope-check-blocked.html";
  const std::string common = "check --port " + sim.port() + " --baud 512000 --seconds 3 --settle-seconds 0.3";
  const CliResult text = run_cli_apart(common);
  const CliResult json = run_cli_apart(common + " --format json --report " + report.string());
  EXPECT_EQ(text.status, 3) << text.out << text.err;
  EXPECT_EQ(failed_ids(json.out), "blockage") << json.out;
  const auto angles_in = [](const std::string& out, const std::string& after) {
    const auto at = out.find(after);
    std::pair<int, int> fromto{-1, -1};
    if (at != std::string::npos)
      std::sscanf(out.c_str() + at + after.size(), " blocked %d°–%d°", &fromto.first, &fromto.second);
    return fromto;
  };
  const auto blockage_json = json.out.find(R"("id":"blockage")");
  ASSERT_NE(blockage_json, std::string::npos) << json.out;
  for (const auto& [out, after] : {std::pair{text.out, std::string("FAIL  blocked sectors")},
                                   std::pair{json.out.substr(blockage_json), std::string(R"("measured":")")}}) {
    const auto [from, to] = angles_in(out, after);
    EXPECT_NEAR(from, 40, 3) << out;
    EXPECT_NEAR(to, 75, 3) << out;
  }
  std::ifstream in(report);
  const std::string html((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  std::filesystem::remove(report);
  const auto row = html.find(R"(<tr data-id="blockage"><td class="v fail">FAIL</td>)");
  ASSERT_NE(row, std::string::npos) << "the report's row";
  EXPECT_NE(html.find("blocked ", row), std::string::npos) << "the report says which sector";
}

// Issue 26: a stall was drawn straight across and named nowhere. Each is now said in the text,
// listed in the JSON and the report, shaded on the report's plot, and the line breaks there.
TEST(CheckCli, StallsAreNamedInEveryFormatAndBreakThePlot) {
  SimOnPty sim(Model::G6, [](SimServerOptions& o) {
    o.device.faults.stall_ms = 400;
    o.device.faults.stall_every_ms = 1200;
  });
  const std::filesystem::path report = std::filesystem::temp_directory_path() / "ydscope-check-stalls.html";
  const CliResult text = run_cli_apart("check --port " + sim.port() +
                                       " --baud 512000 --seconds 3 --settle-seconds 0.3 --report " + report.string());
  EXPECT_NE(text.out.find("interruptions: "), std::string::npos) << text.out;
  EXPECT_NE(text.out.find("s: the stream stalled (about "), std::string::npos) << text.out;
  std::ifstream in(report);
  const std::string html((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  std::filesystem::remove(report);
  EXPECT_NE(html.find(R"(<ul id="gaps"><li>at )"), std::string::npos) << "the report lists no interruption";
  EXPECT_NE(html.find(R"(<rect class="gap")"), std::string::npos) << "the plot shades no interruption";
  std::size_t lines = 0;
  for (auto at = html.find("<polyline"); at != std::string::npos; at = html.find("<polyline", at + 1)) ++lines;
  EXPECT_GE(lines, 2u) << "the scan-rate line runs straight across the stalls";

  const CliResult json = check(sim);
  EXPECT_NE(json.out.find(R"("gaps":[{"from_s":)"), std::string::npos) << json.out;
  EXPECT_NE(json.out.find(R"("cause":"stall")"), std::string::npos) << json.out;
}

TEST(CheckCli, AForcedModelTheDeviceDisagreesWithFailsIdentity) {
  SimOnPty sim(Model::TG50);
  const CliResult run = check(sim, " --model TG30");
  EXPECT_EQ(run.status, 3) << run.out;
  EXPECT_EQ(failed_ids(run.out), "identity") << run.out;
}

TEST(CheckCli, AFlatTargetAtTheRightDistancePassesAndAtTheWrongOneFailsTheBias) {
  // The room's bottom wall: 2400 mm, square to 270 degrees.
  SimOnPty sim(Model::G6);
  const CliResult right = check(sim, " --sector 260:280 --target-mm 2400");
  EXPECT_EQ(right.status, 0) << right.out;
  EXPECT_NE(right.out.find("\"id\":\"range_noise\""), std::string::npos);
  const CliResult wrong = check(sim, " --sector 260:280 --target-mm 2300");
  EXPECT_EQ(wrong.status, 3) << wrong.out;
  EXPECT_EQ(failed_ids(wrong.out), "range_bias") << wrong.out;
  const CliResult strict = check(sim, " --sector 260:280 --target-mm 2400 --noise-mm 2");
  EXPECT_EQ(failed_ids(strict.out), "range_noise") << strict.out;
  const CliResult banded = check(sim, " --sector 260:280 --band 2300:2500 --target-mm 2400");
  EXPECT_EQ(banded.status, 0) << banded.out;
  EXPECT_NE(banded.out.find(R"~("name":"260:280 (2300:2500 mm)")~"), std::string::npos) << banded.out;
}

TEST(CheckCli, MistakesAreUsageErrorsWithOneSentence) {
  SimOnPty sim(Model::G6);
  const std::string port = " --port " + sim.port();
  for (const std::string& args :
       {std::string("check"), "check" + port + " --target-mm 2000", "check" + port + " --sector 10",
        "check" + port + " --format xml", "check" + port + " --tolerance-mm 5", "check" + port + " --seconds 0",
        "check" + port + " --scan-hz 20", "check" + port + " --ranging-khz 5", "check" + port + " --band 1:2",
        "check" + port + " --sector 10:20 --band 5"}) {
    const CliResult run = run_cli(args);
    EXPECT_EQ(run.status, 2) << args << "\n" << run.out;
    EXPECT_NE(run.out.find("ydscope-cli check: "), std::string::npos) << args << "\n" << run.out;
  }
}

TEST(CheckCli, TheReportHoldsEveryCriterionAndThePictures) {
  SimOnPty sim(Model::G6);
  const auto report =
      std::filesystem::path(::testing::TempDir()) / ("check-report-" + std::to_string(getpid()) + ".html");
  const CliResult run = check(sim, " --sector 260:280 --target-mm 2300 --report " + report.string());
  EXPECT_EQ(run.status, 3) << run.out;
  const std::string html = read_text(report);
  std::filesystem::remove(report);
  ASSERT_FALSE(html.empty()) << "no report at " << report;
  EXPECT_EQ(html.rfind("<!DOCTYPE html>", 0), 0u);
  EXPECT_NE(html.find(R"(<span class="verdict fail" id="verdict">FAIL</span>)"), std::string::npos);
  for (const char* id : {"identity", "health", "scan_rate", "scan_jitter", "sample_rate", "link", "valid_returns",
                         "sector_valid", "range_bias", "range_noise"})
    EXPECT_EQ(count(html, std::string("<tr data-id=\"") + id + "\">"), 1u) << id;
  // Each row says what the JSON verdict says (a loaded host may fail more than the bias).
  const std::string failed = "," + failed_ids(run.out) + ",";
  EXPECT_NE(failed.find(",range_bias,"), std::string::npos) << run.out;
  for (const char* id : {"identity", "scan_rate", "link", "range_bias"}) {
    const bool fails = failed.find(std::string(",") + id + ",") != std::string::npos;
    EXPECT_NE(
        html.find(std::string("<tr data-id=\"") + id + "\"><td class=\"v " + (fails ? "fail\">FAIL" : "pass\">PASS")),
        std::string::npos)
        << id;
  }
  EXPECT_EQ(count(html, "<svg "), 4u) << "scan rate, sector histogram, valid share by angle, polar snapshot";
  EXPECT_NE(html.find("<title>Scan rate of each lap over the run</title>"), std::string::npos);
  EXPECT_NE(html.find("<title>Histogram of the sector&#39;s ranges</title>"), std::string::npos);
  EXPECT_NE(html.find("<title>The last lap from above</title>"), std::string::npos);
  EXPECT_EQ(html.find("<script"), std::string::npos) << "self-contained and inert";
  EXPECT_EQ(html.find(" src="), std::string::npos) << "nothing fetched";
  EXPECT_EQ(html.find(" href="), std::string::npos) << "nothing fetched";
}

TEST(CheckCli, AReportThatCannotBeWrittenIsRefusedBeforeConnecting) {
  // /dev/null is no serial port: reaching it would be exit 1, so exit 2 shows the report was checked first.
  const CliResult run = run_cli("check --port /dev/null --report /nonexistent-folder/unit.html");
  EXPECT_EQ(run.status, 2) << run.out;
  EXPECT_NE(run.out.find("the folder /nonexistent-folder does not exist"), std::string::npos) << run.out;
}

// As from every command that opens a port (bad_input_cli_test.cpp), and as the help says.
TEST(CheckCli, AMissingPortIsAUsageError) {
  const CliResult run = run_cli("check --port /nonexistent/ttyUSB9 --seconds 1");
  EXPECT_EQ(run.status, 2) << run.out;
  EXPECT_NE(run.out.find("ydscope-cli check: there is no port /nonexistent/ttyUSB9"), std::string::npos) << run.out;
}

TEST(CheckCli, CtrlCStopsTheMotorAndPrintsWhatWasMeasured) {
  SimOnPty sim(Model::G6);
  const auto report =
      std::filesystem::path(::testing::TempDir()) / ("check-ctrl-c-" + std::to_string(getpid()) + ".html");
  const StartedCli cli = start_cli(
      {"check", "--port", sim.port(), "--seconds", "60", "--settle-seconds", "0.3", "--report", report.string()});
  ASSERT_GE(cli.pid, 0);
  const pid_t child = cli.pid;
  const int out_fd = cli.out_fd;
  // Wait until the lidar has been scanning a while (the virtual lidar counts its laps' packets).
  for (int i = 0; i < 200; ++i) {
    std::uint64_t zero_packets = 0;
    sim.server().with_device([&](VirtualLidar& d) { zero_packets = d.counters().zero_packets; });
    if (zero_packets > 30) break;
    std::this_thread::sleep_for(50ms);
  }
  kill(child, SIGINT);
  std::string out;
  char buffer[4096];
  ssize_t n;
  while ((n = read(out_fd, buffer, sizeof buffer)) > 0) out.append(buffer, static_cast<std::size_t>(n));
  close(out_fd);
  int status = 0;
  waitpid(child, &status, 0);
  ASSERT_TRUE(WIFEXITED(status));
  EXPECT_EQ(WEXITSTATUS(status), 130) << out;
  EXPECT_NE(out.find("(interrupted)"), std::string::npos) << out;
  EXPECT_NE(out.find("PASS  scan rate"), std::string::npos) << out;
  EXPECT_NE(out.find("verdict: INCOMPLETE (interrupted after"), std::string::npos) << out;
  EXPECT_EQ(out.find("verdict: PASS"), std::string::npos) << "a run cut short is never a pass: " << out;
  DeviceMode mode = DeviceMode::Scanning;
  sim.server().with_device([&](VirtualLidar& d) { mode = d.mode(); });
  EXPECT_EQ(mode, DeviceMode::Idle);
  const std::string html = read_text(report);
  std::filesystem::remove(report);
  EXPECT_NE(html.find(R"(id="verdict">INCOMPLETE</span>)"), std::string::npos) << "the report is written, marked";
  EXPECT_NE(html.find("Interrupted after"), std::string::npos);
}

// The lidar unplugged part way through: what was measured is judged, but the run is incomplete
// in every format, never a pass.
TEST(CheckCli, ALinkThatDiesPartWayIsIncompleteNeverAPass) {
  SimOnPty sim(Model::G6);
  std::uint32_t baud = 0;
  sim.server().with_device([&](VirtualLidar& d) { baud = d.profile().default_baud; });
  auto run = std::async(std::launch::async, [&] {
    return run_cli_apart("check --port " + sim.port() + " --baud " + std::to_string(baud) +
                         " --seconds 6 --settle-seconds 0.3 --format json");
  });
  // Unplug once the measurement is under way (about 30 laps of the virtual G6 at 8 Hz).
  for (int i = 0; i < 200; ++i) {
    std::uint64_t zero_packets = 0;
    sim.server().with_device([&](VirtualLidar& d) { zero_packets = d.counters().zero_packets; });
    if (zero_packets > 30) break;
    std::this_thread::sleep_for(50ms);
  }
  sim.server().unplug();
  const CliResult result = run.get();
  EXPECT_EQ(result.status, 1) << result.out << result.err;
  EXPECT_NE(result.out.find(R"({"type":"check","verdict":"incomplete")"), std::string::npos) << result.out;
  EXPECT_EQ(result.out.find(R"("failure":null)"), std::string::npos) << "the failure is named: " << result.out;
}

}  // namespace
}  // namespace ydscope
