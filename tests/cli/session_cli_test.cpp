// ydscope-cli info, scan and set, run as a user would against the virtual lidar on a
// pseudo-terminal: one JSON object (or N laps and a summary), and a sentence plus exit 1 on failure.
#include <sys/ioctl.h>

#include <gtest/gtest.h>

#include <csignal>
#include <fstream>
#include <string>
#include <thread>

#include <sys/wait.h>
#include <unistd.h>

#include "cli/cli_run_support.h"
#include "support/session_test_support.h"

namespace ydscope {
namespace {

using namespace test;

TEST(SessionCli, InfoPrintsOneJsonObjectWithTheDeviceDetails) {
  SimOnPty sim(Model::TG50);
  const CliResult run = run_cli("info --port " + sim.port());
  ASSERT_EQ(run.status, 0) << run.out;
  EXPECT_EQ(count(run.out, "\n"), 1u) << run.out;
  for (const char* field : {"\"model\":\"TG50\"", "\"model_code\":102", "\"firmware\":\"1.2\"", "\"hardware\":1",
                            "\"serial\":", "\"summary\":\"ok\"", "\"scan_hz\":", "\"ranging_khz\":9"})
    EXPECT_NE(run.out.find(field), std::string::npos) << field << " in " << run.out;
}

TEST(SessionCli, AForcedModelThatDisagreesWithTheDeviceIsWarnedAbout) {
  SimOnPty sim(Model::TG50);
  const CliResult forced = run_cli("info --port " + sim.port() + " --model G6");
  ASSERT_EQ(forced.status, 0) << forced.out;
  EXPECT_NE(forced.out.find("warning: the device reports model code 102 (TG50) but G6 was asked for"),
            std::string::npos)
      << forced.out;
  const CliResult matching = run_cli("info --port " + sim.port() + " --model TG50");
  ASSERT_EQ(matching.status, 0) << matching.out;
  EXPECT_EQ(matching.out.find("warning"), std::string::npos) << matching.out;
}

TEST(SessionCli, ScanPrintsNLapsAndTheSummary) {
  SimOnPty sim(Model::G1);
  const CliResult run = run_cli("scan --port " + sim.port() + " --model G1 --laps 4");
  ASSERT_EQ(run.status, 0) << run.out.substr(0, 400);
  EXPECT_EQ(count(run.out, "{\"type\":\"lap\""), 4u);
  EXPECT_EQ(count(run.out, "{\"type\":\"summary\""), 1u);
  EXPECT_NE(run.out.find("\"crc_ok\":true"), std::string::npos);
  DeviceMode mode = DeviceMode::Scanning;
  sim.server().with_device([&](VirtualLidar& d) { mode = d.mode(); });
  EXPECT_EQ(mode, DeviceMode::Idle) << "scan leaves the lidar stopped";
}

// A bad line (here one packet in six or so broken) is said on stderr, where a user piping CSV or
// recording to a file looks; the laps still come out. The fault matrix checks that a lightly
// corrupted run says nothing.
TEST(SessionCli, ScanAndRecordSayWhenManyPacketsFailTheirChecksum) {
  SimOnPty sim(Model::G6, [](SimServerOptions& o) { o.device.faults.corrupt_byte_rate = 2e-3; });
  const CliResult scan = run_cli_apart("scan --port " + sim.port() + " --laps 8 --format csv");
  ASSERT_EQ(scan.status, 0) << scan.err;
  EXPECT_EQ(scan.out.rfind("lap,", 0), 0u) << "the CSV is still CSV: " << scan.out.substr(0, 200);
  EXPECT_EQ(scan.err.rfind("ydscope-cli scan: warning: ", 0), 0u) << scan.err;
  EXPECT_NE(scan.err.find("failed their checksum and were dropped; check the cable"), std::string::npos) << scan.err;
  EXPECT_EQ(count(scan.err, "\n"), 1u) << "one sentence: " << scan.err;

  const std::string out = sim.port() + "-run.ydrec";
  const CliResult record = run_cli_apart("record --port " + sim.port() + " --out " + out + " --seconds 2");
  ASSERT_EQ(record.status, 0) << record.err;
  EXPECT_EQ(record.err.rfind("ydscope-cli record: warning: ", 0), 0u) << record.err;
  EXPECT_NE(record.err.find("failed their checksum"), std::string::npos) << record.err;
}

TEST(SessionCli, SetReachesTheTargetAndPrintsTheReadBack) {
  SimOnPty sim(Model::G6);
  const CliResult hz = run_cli("set --port " + sim.port() + " --scan-hz 9.4");
  ASSERT_EQ(hz.status, 0) << hz.out;
  EXPECT_NE(hz.out.find("\"scan_hz\":9.4"), std::string::npos) << hz.out;
  const CliResult khz = run_cli("set --port " + sim.port() + " --ranging-khz 4");
  ASSERT_EQ(khz.status, 0) << khz.out;
  EXPECT_NE(khz.out.find("\"ranging_khz\":4"), std::string::npos) << khz.out;
  std::uint32_t centihz = 0;
  std::uint16_t ranging = 0;
  sim.server().with_device([&](VirtualLidar& d) {
    centihz = d.scan_centihz();
    ranging = d.ranging_khz();
  });
  EXPECT_EQ(centihz, 940u);
  EXPECT_EQ(ranging, 4u);
}

TEST(SessionCli, SetExitsOneWhenTheTargetCannotBeReached) {
  SimOnPty sim(Model::G1);
  const CliResult run = run_cli("set --port " + sim.port() + " --ranging-khz 8");
  EXPECT_EQ(run.status, 1) << run.out;
  EXPECT_NE(run.out.find("read-only"), std::string::npos) << run.out;
}

TEST(SessionCli, FailuresAreOneSentenceAndANonZeroExit) {
  const CliResult missing = run_cli("info --port /dev/ydscope-no-such-port");
  EXPECT_EQ(missing.status, 2);  // a port that does not exist is a usage error, as the help says
  EXPECT_EQ(count(missing.out, "\n"), 1u) << missing.out;
  EXPECT_NE(missing.out.find("/dev/ydscope-no-such-port"), std::string::npos) << missing.out;
  EXPECT_EQ(run_cli("info --port tcp://nowhere").status, 2);
  EXPECT_EQ(run_cli("info --port /dev/null --model G7").status, 2);
  EXPECT_EQ(run_cli("scan --port /dev/null").status, 2) << "--laps is required";
  EXPECT_EQ(run_cli("set --port /dev/null").status, 2) << "a target is required";
}

// `scan --laps 1000 | head -1`: the reader goes away after one line. The lidar must be stopped
// before ydscope-cli ends (a real unit would otherwise keep spinning), and it ends as a closed
// pipe ends any program: by SIGPIPE, quietly.
TEST(SessionCli, AReaderThatGoesAwayStopsTheLidarFirst) {
  SimOnPty sim(Model::G6);
  const StartedCli cli = start_cli({"scan", "--port", sim.port(), "--laps", "1000"});
  ASSERT_GE(cli.pid, 0);
  const pid_t child = cli.pid;
  std::string first;
  char c = 0;
  while (read(cli.out_fd, &c, 1) == 1 && c != '\n') first += c;
  close(cli.out_fd);  // head -1 is done
  EXPECT_NE(first.find("{\"type\":\"lap\""), std::string::npos) << first.substr(0, 80);
  int status = 0;
  bool ended = false;
  for (int i = 0; i < 200 && !ended; ++i) {
    ended = waitpid(child, &status, WNOHANG) == child;
    if (!ended) std::this_thread::sleep_for(50ms);
  }
  if (!ended) {  // never leave it running past the test
    kill(child, SIGKILL);
    waitpid(child, &status, 0);
    FAIL() << "ydscope-cli scan did not end within 10 s of its reader going away";
  }
  ASSERT_TRUE(WIFSIGNALED(status) && WTERMSIG(status) == SIGPIPE) << "status " << status;
  DeviceMode mode = DeviceMode::Scanning;
  sim.server().with_device([&](VirtualLidar& d) { mode = d.mode(); });
  EXPECT_EQ(mode, DeviceMode::Idle) << "the lidar was left scanning";
}

// `scan ... | slow-reader`: the reader stops reading and the pipe fills, so scan's output cannot
// go on. SIGTERM must still end it with the lidar stopped (issue 26: "a full stdout"). Under load
// a signal that broke a write partway used to be lost: stdio wrote the rest and blocked again.
TEST(SessionCli, ASignalEndsAScanBlockedOnAFullPipeAndStopsTheLidar) {
  SimOnPty sim(Model::G6);
  const StartedCli cli = start_cli({"scan", "--port", sim.port(), "--laps", "100000", "--format", "csv"});
  ASSERT_GE(cli.pid, 0);
  const pid_t child = cli.pid;
  // Until the pipe holds nearly its 64 KiB: no lap more fits, and scan waits on its reader.
  const auto waiting_in = [child] {
    std::ifstream wchan("/proc/" + std::to_string(child) + "/wchan");
    std::string where;
    std::getline(wchan, where);
    return where;
  };
  const auto blocked = [&] {
    int queued = 0;
    ioctl(cli.out_fd, FIONREAD, &queued);
    return queued > 60000;
  };
  for (int i = 0; i < 400 && !blocked(); ++i) std::this_thread::sleep_for(50ms);
  ASSERT_TRUE(blocked()) << "scan never blocked on its full output (it waits in " << waiting_in() << ")";
  kill(child, SIGTERM);
  int status = 0;
  bool ended = false;
  for (int i = 0; i < 200 && !ended; ++i) {
    ended = waitpid(child, &status, WNOHANG) == child;
    if (!ended) std::this_thread::sleep_for(50ms);
  }
  close(cli.out_fd);
  if (!ended) {
    kill(child, SIGKILL);
    waitpid(child, &status, 0);
    FAIL() << "ydscope-cli scan did not end within 10 s of SIGTERM while its output was blocked";
  }
  EXPECT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 0) << "status " << status;
  DeviceMode mode = DeviceMode::Scanning;
  sim.server().with_device([&](VirtualLidar& d) { mode = d.mode(); });
  EXPECT_EQ(mode, DeviceMode::Idle) << "the lidar was left scanning";
}

}  // namespace
}  // namespace ydscope
