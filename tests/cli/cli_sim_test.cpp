// `ydscope-cli sim` run as a user would: a subprocess, its stdout, its symlink, and signals.
#include <gtest/gtest.h>
#include <poll.h>
#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <string>
#include <thread>
#include <vector>

#include "sim/host_port.h"
#include "support/temp_dir.h"

extern char** environ;

namespace ydscope {
namespace {

using namespace std::chrono_literals;

// A child process with its stdout and stderr on pipes.
class Child {
 public:
  explicit Child(std::vector<std::string> args) {
    args.insert(args.begin(), YDSCOPE_CLI_PATH);
    int out[2];
    int err[2];
    EXPECT_EQ(::pipe(out), 0);
    EXPECT_EQ(::pipe(err), 0);
    posix_spawn_file_actions_t actions;
    posix_spawn_file_actions_init(&actions);
    posix_spawn_file_actions_adddup2(&actions, out[1], 1);
    posix_spawn_file_actions_adddup2(&actions, err[1], 2);
    posix_spawn_file_actions_addclose(&actions, out[0]);
    posix_spawn_file_actions_addclose(&actions, err[0]);
    std::vector<char*> argv;
    for (auto& arg : args) argv.push_back(arg.data());
    argv.push_back(nullptr);
    EXPECT_EQ(::posix_spawn(&pid_, argv[0], &actions, nullptr, argv.data(), environ), 0);
    posix_spawn_file_actions_destroy(&actions);
    ::close(out[1]);
    ::close(err[1]);
    out_ = out[0];
    err_ = err[0];
  }
  ~Child() {
    if (pid_ > 0 && !reaped_) {
      ::kill(pid_, SIGKILL);
      ::waitpid(pid_, nullptr, 0);
    }
    ::close(out_);
    ::close(err_);
  }

  // One line of stdout, or "" after the timeout.
  std::string read_line(std::chrono::milliseconds timeout) {
    std::string line;
    const auto end = std::chrono::steady_clock::now() + timeout;
    while (std::chrono::steady_clock::now() < end) {
      pollfd p{out_, POLLIN, 0};
      if (::poll(&p, 1, 50) <= 0) continue;
      char c = 0;
      if (::read(out_, &c, 1) != 1) break;
      if (c == '\n') return line;
      line += c;
    }
    return "";
  }

  // Everything the child wrote (call after it exited).
  std::string read_stdout() { return read_all(out_); }
  std::string read_stderr() { return read_all(err_); }

  void signal(int number) { ::kill(pid_, number); }

  // Exit status, or -1 if it did not exit within the timeout.
  int wait(std::chrono::milliseconds timeout) {
    const auto end = std::chrono::steady_clock::now() + timeout;
    while (std::chrono::steady_clock::now() < end) {
      int status = 0;
      if (::waitpid(pid_, &status, WNOHANG) == pid_) {
        reaped_ = true;
        return WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
      }
      std::this_thread::sleep_for(10ms);
    }
    return -1;
  }

 private:
  static std::string read_all(int fd) {
    std::string text;
    char buffer[512];
    ssize_t n = 0;
    while ((n = ::read(fd, buffer, sizeof buffer)) > 0) text.append(buffer, static_cast<std::size_t>(n));
    return text;
  }

  pid_t pid_ = -1;
  int out_ = -1;
  int err_ = -1;
  bool reaped_ = false;
};

TEST(CliSim, PtyReadyLinkAndCleanExitOnSigterm) {
  const test::TempDir dir("cli-sim");
  const std::string link = (dir / "lidar").string();
  Child child({"sim", "--model", "g6", "--pty", link, "--scene", "room", "--seed", "3"});
  const std::string line = child.read_line(10s);
  ASSERT_EQ(line.rfind("ready /dev/pts/", 0), 0u) << "stdout: '" << line << "'";
  const std::string device = line.substr(6);
  EXPECT_EQ(std::filesystem::read_symlink(link).string(), device);

  test::HostPort host;  // it is a working lidar
  ASSERT_TRUE(host.open_device(link));
  ASSERT_TRUE(host.send({0xA5, 0x90}));
  const auto reply = host.read(27, 3s);
  ASSERT_EQ(reply.size(), 27u);
  EXPECT_EQ(reply[7], 13);  // G6
  host.close();

  child.signal(SIGTERM);
  EXPECT_EQ(child.wait(10s), 0);
  EXPECT_FALSE(std::filesystem::exists(std::filesystem::symlink_status(link)));
}

TEST(CliSim, SigintAlsoExitsCleanlyOnTcpAndVerboseTellsWhatHappened) {
  Child child({"sim", "--model", "TG15", "--tcp", "127.0.0.1:0", "--verbose"});
  const std::string line = child.read_line(10s);
  ASSERT_EQ(line.rfind("ready tcp://127.0.0.1:", 0), 0u) << line;
  const auto port = static_cast<std::uint16_t>(std::stoi(line.substr(line.rfind(':') + 1)));
  test::HostPort host;
  ASSERT_TRUE(host.connect_tcp(port));
  ASSERT_TRUE(host.send({0xA5, 0x90}));
  const auto reply = host.read(27, 3s);
  ASSERT_EQ(reply.size(), 27u);
  EXPECT_EQ(reply[7], 100);  // TG15
  ASSERT_TRUE(host.send({0xA5, 0x60, 0xA5, 0x65}));
  host.read(100'000, 500ms);
  child.signal(SIGINT);
  EXPECT_EQ(child.wait(10s), 0);
  const std::string log = child.read_stderr();
  for (const char* event : {"received A5 90 (device info)", "scanning at 10.00 Hz", "idle: stopped by A5 65"})
    EXPECT_NE(log.find(event), std::string::npos) << event << " not in:\n" << log;
}

TEST(CliSim, UnknownModelListsTheValidOnes) {
  Child child({"sim", "--model", "X4", "--pty", "/tmp/never-made"});
  EXPECT_EQ(child.wait(10s), 2);
  const std::string err = child.read_stderr();
  EXPECT_NE(err.find("unknown model 'X4'"), std::string::npos) << err;
  EXPECT_NE(err.find("G1, G6, TG15, TG30, TG50"), std::string::npos) << err;
  EXPECT_EQ(std::count(err.begin(), err.end(), '\n'), 1);
}

TEST(CliSim, ExistingLinkPathIsRefusedAndKept) {
  const test::TempDir dir("cli-sim");
  const std::string link = (dir / "file").string();
  std::ofstream(link) << "keep";
  Child child({"sim", "--model", "G1", "--pty", link});
  EXPECT_EQ(child.wait(10s), 1);
  EXPECT_NE(child.read_stderr().find("already exists"), std::string::npos);
  EXPECT_TRUE(std::filesystem::is_regular_file(link));
}

TEST(CliSim, NeedsExactlyOneTransport) {
  Child neither({"sim", "--model", "G1"});
  EXPECT_EQ(neither.wait(10s), 2);
  EXPECT_NE(neither.read_stderr().find("exactly one of --pty"), std::string::npos);
  Child both({"sim", "--model", "G1", "--pty", "/tmp/x", "--tcp", "127.0.0.1:0"});
  EXPECT_EQ(both.wait(10s), 2);
}

// Issue 17: a stall as long as its period was accepted, and the virtual lidar went silent for good.
TEST(CliSim, AStallMustBeShorterThanItsPeriod) {
  for (const char* stall : {"1000", "1500"}) {
    Child child(
        {"sim", "--model", "G6", "--pty", "/tmp/ydscope-never", "--stall-ms", stall, "--stall-every-ms", "1000"});
    EXPECT_EQ(child.wait(10s), 2) << stall;
    EXPECT_EQ(child.read_stderr(), "ydscope-cli sim: --stall-ms (" + std::string(stall) +
                                       ") must be shorter than --stall-every-ms (1000), or the virtual lidar never "
                                       "sends again\n");
  }
}

TEST(CliSim, AMotorOffItsSetRateShowsInG1sOwnRateReport) {
  // G1's CT carries the rate the motor really turns at: set 9 Hz (the default), turning 1 Hz fast.
  Child child({"sim", "--model", "G1", "--tcp", "127.0.0.1:0", "--scan-offset-hz", "1"});
  const std::string line = child.read_line(10s);
  ASSERT_EQ(line.rfind("ready tcp://", 0), 0u) << line;
  const std::string command = std::string("'") + YDSCOPE_CLI_PATH + "' scan --port " + line.substr(6) + " --laps 4";
  std::FILE* scan = ::popen(command.c_str(), "r");
  ASSERT_NE(scan, nullptr);
  std::string laps;
  char buffer[4096];
  while (std::fgets(buffer, sizeof buffer, scan)) laps += buffer;
  EXPECT_EQ(::pclose(scan), 0) << laps.substr(0, 300);
  EXPECT_NE(laps.find(R"("scan_hz":10,)"), std::string::npos) << laps.substr(0, 300);
  EXPECT_EQ(laps.find(R"("scan_hz":9,)"), std::string::npos);
}

TEST(CliSim, ASecondHostIsTurnedAwayAndToldWhy) {
  Child child({"sim", "--model", "G6", "--tcp", "127.0.0.1:0"});
  const std::string line = child.read_line(10s);
  ASSERT_EQ(line.rfind("ready tcp://", 0), 0u) << line;
  test::HostPort first;  // the host that holds the virtual lidar
  ASSERT_TRUE(first.connect_tcp(static_cast<std::uint16_t>(std::stoi(line.substr(line.rfind(':') + 1)))));
  ASSERT_TRUE(first.send({0xA5, 0x90}));
  ASSERT_EQ(first.read(27, 3s).size(), 27u) << "the first host is served";
  const std::string command = std::string("'") + YDSCOPE_CLI_PATH + "' info --port " + line.substr(6) + " 2>&1";
  std::FILE* info = ::popen(command.c_str(), "r");
  ASSERT_NE(info, nullptr);
  std::string said;
  char buffer[1024];
  while (std::fgets(buffer, sizeof buffer, info)) said += buffer;
  const int status = ::pclose(info);
  EXPECT_EQ(WEXITSTATUS(status), 1) << said;
  EXPECT_NE(said.find("closed before it sent a byte: another program may be connected to it already"),
            std::string::npos)
      << said;
}

TEST(CliSim, MotorFaultsOutsideTheirSpanAreUsageErrors) {
  for (const std::vector<std::string>& args :
       {std::vector<std::string>{"--scan-offset-hz", "6"}, std::vector<std::string>{"--scan-wobble-hz", "-1"}}) {
    std::vector<std::string> all{"sim", "--model", "G6", "--pty", "/tmp/ydscope-never"};
    all.insert(all.end(), args.begin(), args.end());
    Child child(all);
    EXPECT_EQ(child.wait(10s), 2) << args[0];
    EXPECT_NE(child.read_stderr().find(args[0]), std::string::npos) << args[0];
  }
}

TEST(CliSim, HelpExplainsEveryFaultOption) {
  Child child({"sim", "--help"});
  EXPECT_EQ(child.wait(10s), 0);
  const std::string help = child.read_stdout();
  for (const char* option : {"--corrupt", "--drop", "--lose-packets", "--stall-ms", "--stall-every-ms", "--health-bits",
                             "--junk", "--unplug-after-ms", "--replug-after-ms", "--zero-log", "--scene", "--seed",
                             "--scan-offset-hz", "--scan-wobble-hz"})
    EXPECT_NE(help.find(option), std::string::npos) << option;
}

}  // namespace
}  // namespace ydscope

namespace ydscope {
namespace {

// Issue 15: the vendor-SDK host mode, a chosen firmware and a USB-bridge delivery, through the pty.
TEST(CliSim, HostCompatFirmwareAndDeliveryReachTheHost) {
  const test::TempDir dir("cli-sim");
  const std::string link = (dir / "ydlidar").string();
  Child child({"sim", "--model", "TG30", "--pty", link, "--host-compat", "ydlidar-sdk", "--firmware", "1.1",
               "--delivery", "burst:64:1000"});
  ASSERT_EQ(child.read_line(10s).rfind("ready /dev/pts/", 0), 0u);
  test::HostPort host;
  ASSERT_TRUE(host.open_device(link));
  ASSERT_TRUE(host.send({0xA5, 0x92}));  // the SDK's health request, not in the TG manual
  EXPECT_EQ(host.read(10, 3s), (std::vector<std::uint8_t>{0xA5, 0x5A, 0x03, 0x00, 0x00, 0x00, 0x06, 0x00, 0x00, 0x00}));
  ASSERT_TRUE(host.send({0xA5, 0x90}));
  const auto info = host.read(27, 3s);
  ASSERT_EQ(info.size(), 27u);
  EXPECT_EQ(info[7], 101);  // TG30
  EXPECT_EQ(info[8], 1);    // firmware 1.1: low byte major, high byte minor (the manual's order)
  EXPECT_EQ(info[9], 1);
  ASSERT_TRUE(host.send({0xA5, 0x93}));
  EXPECT_EQ(host.read(11, 3s),
            (std::vector<std::uint8_t>{0xA5, 0x5A, 0x04, 0x00, 0x00, 0x00, 0x04, 0x00, 0x00, 0x00, 0x00}));
  host.close();
  child.signal(SIGTERM);
  EXPECT_EQ(child.wait(10s), 0);
}

TEST(CliSim, BadHostCompatFirmwareOrDeliveryIsOneSentence) {
  const std::vector<std::pair<std::vector<std::string>, std::string>> cases{
      {{"--host-compat", "sdk"}, "unknown --host-compat 'sdk'; the choices are manual, ydlidar-sdk"},
      {{"--firmware", "1"}, "--firmware needs MAJOR.MINOR"},
      {{"--firmware", "4.0"}, "major 0..3 and minor 0..31 on the G1"},
      {{"--delivery", "bursts"}, "the delivery models are whole, burst:BYTES:US"},
      {{"--delivery", "random:0"}, "random needs the largest write"},
  };
  for (const auto& [extra, message] : cases) {
    std::vector<std::string> args{"sim", "--model", "G1", "--pty", "/tmp/ydscope-never"};
    args.insert(args.end(), extra.begin(), extra.end());
    Child child(args);
    EXPECT_EQ(child.wait(10s), 2) << extra[0];
    const std::string err = child.read_stderr();
    EXPECT_NE(err.find(message), std::string::npos) << err;
    EXPECT_EQ(std::count(err.begin(), err.end(), '\n'), 1) << err;
  }
}

TEST(CliSim, HelpExplainsTheHostOptions) {
  Child child({"sim", "--help"});
  EXPECT_EQ(child.wait(10s), 0);
  const std::string help = child.read_stdout();
  for (const char* option :
       {"--host-compat", "ydlidar-sdk", "--firmware", "--delivery", "burst:BYTES:US", "random:MAX"})
    EXPECT_NE(help.find(option), std::string::npos) << option;
}

}  // namespace
}  // namespace ydscope
