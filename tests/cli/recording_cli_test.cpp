// ydscope-cli record / replay / decode of recordings, run as a user would, against the virtual
// lidar on a pseudo-terminal: the recording holds the start-up exchange and the scan, replay and
// decode agree lap for lap, Ctrl-C and SIGKILL leave a readable file.
#include <fcntl.h>
#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <regex>
#include <string>
#include <thread>
#include <vector>

#include <gtest/gtest.h>

#include "core/record/recording_reader.h"
#include "core/record/recording_writer.h"
#include "core/sim/sim_server.h"
#include "test_data.h"
#include "support/temp_dir.h"

extern char** environ;

namespace ydscope {
namespace {

namespace fs = std::filesystem;

struct CliRun {
  std::string out;
  std::string err;
  int status = -1;
};

class RecordingCli : public ::testing::Test {
 protected:
  void TearDown() override {
    if (sim_) sim_->stop();
  }

  std::string path(const std::string& name) const { return (dir_ / name).string(); }

  std::string start_sim(Model model) {
    SimServerOptions options;
    options.device.model = model;
    options.device.scene = "room";
    sim_ = std::make_unique<SimServer>(options);
    sim_->start();
    return sim_->device_path();
  }

  static std::string slurp(const std::string& file) {
    std::ifstream in(file, std::ios::binary);
    return std::string(std::istreambuf_iterator<char>(in), {});
  }

  // Starts the CLI with `args`, stdout and stderr to files in the test folder.
  pid_t spawn(const std::vector<std::string>& args) {
    std::vector<std::string> argv_text{YDSCOPE_CLI_PATH};
    argv_text.insert(argv_text.end(), args.begin(), args.end());
    std::vector<char*> argv;
    for (auto& a : argv_text) argv.push_back(a.data());
    argv.push_back(nullptr);
    posix_spawn_file_actions_t actions;
    posix_spawn_file_actions_init(&actions);
    posix_spawn_file_actions_addopen(&actions, 1, path("stdout").c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    posix_spawn_file_actions_addopen(&actions, 2, path("stderr").c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    pid_t pid = -1;
    const int rc = ::posix_spawn(&pid, argv[0], &actions, nullptr, argv.data(), environ);
    posix_spawn_file_actions_destroy(&actions);
    EXPECT_EQ(rc, 0);
    return pid;
  }
  CliRun finish(pid_t pid) {
    CliRun run;
    int status = 0;
    ::waitpid(pid, &status, 0);
    run.status = WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
    run.out = slurp(path("stdout"));
    run.err = slurp(path("stderr"));
    return run;
  }
  CliRun run(const std::vector<std::string>& args) { return finish(spawn(args)); }

  // Waits (at most 20 s, a hang guard) until the recording holds at least `bytes` device bytes.
  static bool wait_for_device_bytes(const std::string& file, std::uint64_t bytes) {
    const auto give_up = std::chrono::steady_clock::now() + std::chrono::seconds(20);
    while (std::chrono::steady_clock::now() < give_up) {
      std::string error;
      const auto summary = fs::exists(file) ? summarize_recording(file, error) : std::nullopt;
      if (summary && summary->device_bytes >= bytes) return true;
      std::this_thread::sleep_for(std::chrono::milliseconds(50));
    }
    return false;
  }

  static std::size_t count_laps(const std::string& jsonl) {
    std::size_t laps = 0;
    for (std::size_t at = jsonl.find("{\"type\":\"lap\""); at != std::string::npos;
         at = jsonl.find("{\"type\":\"lap\"", at + 1))
      ++laps;
    return laps;
  }

  test::TempDir dir_{"recording-cli"};
  std::unique_ptr<SimServer> sim_;
};

TEST_F(RecordingCli, RecordHoldsStartUpAndScanAndReplayMatchesDecode) {
  const std::string port = start_sim(Model::G1);
  const std::string file = path("g1.ydrec");
  const CliRun record = run({"record", "--port", port, "--out", file, "--seconds", "1.5"});
  ASSERT_EQ(record.status, 0) << record.err;
  std::smatch match;
  ASSERT_TRUE(std::regex_search(record.out, match,
                                std::regex("^recorded .*g1\\.ydrec: [0-9.]+ s, ([0-9]+) bytes from the device, "
                                           "([0-9]+) bytes to it, ([0-9]+) laps\n$")))
      << record.out;
  const std::size_t laps = std::stoul(match[3]);
  EXPECT_GE(laps, 3u);  // G1 defaults to several laps a second

  std::string error;
  auto reader = RecordingReader::open(file, error);
  ASSERT_TRUE(reader) << error;
  std::vector<std::uint8_t> sent;
  std::uint64_t received = 0;
  RecordView record_view;
  while (reader->next(record_view)) {
    if (record_view.type == RecordType::HostToDevice)
      sent.insert(sent.end(), record_view.payload.begin(), record_view.payload.end());
    if (record_view.type == RecordType::DeviceToHost) received += record_view.payload.size();
  }
  EXPECT_FALSE(reader->truncated());
  EXPECT_EQ(std::to_string(received), match[1].str());
  EXPECT_EQ(std::to_string(sent.size()), match[2].str());
  const auto has_command = [&sent](std::uint8_t code) {
    for (std::size_t i = 0; i + 1 < sent.size(); ++i)
      if (sent[i] == 0xA5 && sent[i + 1] == code) return true;
    return false;
  };
  EXPECT_TRUE(has_command(0x90)) << "device info request missing from the recording";
  EXPECT_TRUE(has_command(0x60)) << "scan command missing from the recording";
  const auto& metadata = reader->metadata();
  EXPECT_EQ(metadata.model, "G1");  // detected by the session, added after the start
  EXPECT_EQ(metadata.model_code, 19u);
  EXPECT_EQ(metadata.baud, 230400u);
  EXPECT_EQ(metadata.port, port);
  EXPECT_TRUE(metadata.serial && !metadata.serial->empty());
  EXPECT_TRUE(metadata.start_wall_time.has_value());

  const CliRun replay = run({"replay", file, "--speed", "0"});
  ASSERT_EQ(replay.status, 0) << replay.err;
  const CliRun decode = run({"decode", file});
  ASSERT_EQ(decode.status, 0) << decode.err;
  EXPECT_EQ(replay.out, decode.out);
  EXPECT_EQ(count_laps(replay.out), laps);
  EXPECT_NE(replay.out.find("{\"type\":\"summary\",\"bytes\":" + match[1].str() + ","), std::string::npos);

  // Decoding as another model is the user's call.
  const CliRun as_g6 = run({"decode", "--model", "G6", "--format", "summary", file});
  EXPECT_EQ(as_g6.status, 0) << as_g6.err;
}

TEST_F(RecordingCli, ReplayAtRecordedSpeedGivesTheSameLaps) {
  const std::string port = start_sim(Model::G6);
  const std::string file = path("g6.ydrec");
  ASSERT_EQ(run({"record", "--port", port, "--out", file, "--seconds", "0.6"}).status, 0);
  const CliRun timed = run({"replay", file, "--format", "summary"});
  const CliRun fast = run({"replay", file, "--speed", "0", "--format", "summary"});
  ASSERT_EQ(timed.status, 0) << timed.err;
  EXPECT_EQ(timed.out, fast.out);
}

// Ctrl-C, and a closed terminal or ssh session (SIGHUP) alike.
TEST_F(RecordingCli, CtrlCClosesTheFileCleanly) {
  for (const int signal : {SIGINT, SIGHUP}) {
    SCOPED_TRACE(signal == SIGINT ? "SIGINT" : "SIGHUP");
    const std::string port = start_sim(Model::G6);
    const std::string file = path("interrupted-" + std::to_string(signal) + ".ydrec");
    const pid_t pid = spawn({"record", "--port", port, "--out", file});
    ASSERT_TRUE(wait_for_device_bytes(file, 2000));
    ::kill(pid, signal);
    const CliRun result = finish(pid);
    EXPECT_EQ(result.status, 0) << result.err;
    EXPECT_EQ(result.out.rfind("recorded ", 0), 0u) << result.out;
    DeviceMode mode = DeviceMode::Scanning;
    for (int i = 0; i < 50 && mode != DeviceMode::Idle; ++i) {  // the virtual lidar reads it on its thread
      sim_->with_device([&](VirtualLidar& d) { mode = d.mode(); });
      if (mode != DeviceMode::Idle) std::this_thread::sleep_for(std::chrono::milliseconds(20));
    }
    EXPECT_EQ(mode, DeviceMode::Idle) << "the lidar was left scanning";
    std::string error;
    const auto summary = summarize_recording(file, error);
    ASSERT_TRUE(summary) << error;
    EXPECT_TRUE(summary->warning.empty()) << summary->warning;
    EXPECT_TRUE(summary->error.empty()) << summary->error;
    EXPECT_GE(summary->device_bytes, 2000u);
  }
}

TEST_F(RecordingCli, KilledRecorderLeavesAReadableFile) {
  const std::string port = start_sim(Model::G6);
  const std::string file = path("killed.ydrec");
  const pid_t pid = spawn({"record", "--port", port, "--out", file});
  ASSERT_TRUE(wait_for_device_bytes(file, 4000));
  ::kill(pid, SIGKILL);
  finish(pid);
  std::string error;
  const auto summary = summarize_recording(file, error);
  ASSERT_TRUE(summary) << error;
  EXPECT_TRUE(summary->error.empty()) << summary->error;  // at worst a truncated tail
  EXPECT_GE(summary->device_bytes, 4000u);
  EXPECT_EQ(summary->metadata.model, "G6");
  const CliRun replay = run({"replay", file, "--speed", "0", "--format", "summary"});
  EXPECT_EQ(replay.status, 0) << replay.err;
}

TEST_F(RecordingCli, UsageAndFailureSentences) {
  CliRun result = run({"record", "--port", "/dev/ttyDOESNOTEXIST9"});
  EXPECT_EQ(result.status, 2);
  EXPECT_NE(result.err.find("--out"), std::string::npos) << result.err;

  const std::string existing = path("existing.ydrec");
  std::ofstream(existing) << "x";
  result = run({"record", "--port", "/dev/ttyDOESNOTEXIST9", "--out", existing});
  EXPECT_EQ(result.status, 2);
  EXPECT_NE(result.err.find("already exists; choose another --out or add --force"), std::string::npos) << result.err;

  result = run({"record", "--port", "/dev/ttyDOESNOTEXIST9", "--out", path("nope.ydrec")});
  EXPECT_EQ(result.status, 2);  // as the help says, and as every command says it
  EXPECT_NE(result.err.find("there is no port /dev/ttyDOESNOTEXIST9"), std::string::npos) << result.err;
  EXPECT_EQ(std::count(result.err.begin(), result.err.end(), '\n'), 1) << result.err;
  EXPECT_FALSE(fs::exists(path("nope.ydrec")));  // nothing was recorded: no empty file left behind

  const std::string raw = (test::captures_dir() / "x4-scan1.bin").string();
  result = run({"replay", raw});
  EXPECT_EQ(result.status, 1);
  EXPECT_NE(result.err.find("is not a ydscope recording"), std::string::npos) << result.err;
  EXPECT_EQ(run({"replay"}).status, 2);
  EXPECT_EQ(run({"replay", raw, "--speed", "-1"}).status, 2);

  // A recording that does not name its model needs --model.
  const std::string anonymous = path("anonymous.ydrec");
  {
    std::string error;
    auto writer = RecordingWriter::create(anonymous, {}, 0, error);
    ASSERT_TRUE(writer) << error;
    const std::vector<std::uint8_t> bytes{0xAA, 0x55, 0x01, 0x01};
    writer->append(Direction::DeviceToHost, bytes, 10);
  }
  result = run({"decode", anonymous});
  EXPECT_EQ(result.status, 2);
  EXPECT_NE(result.err.find("does not say which lidar made it; pass --model"), std::string::npos) << result.err;
  result = run({"replay", anonymous, "--model", "G6", "--speed", "0", "--format", "summary"});
  EXPECT_EQ(result.status, 0) << result.err;
  EXPECT_NE(result.out.find("\"bytes\":4,"), std::string::npos) << result.out;
}

}  // namespace
}  // namespace ydscope
