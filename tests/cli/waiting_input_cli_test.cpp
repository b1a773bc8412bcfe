// Issue 26: a FIFO that never writes, or /dev/zero, blocked decode, replay, export and the app
// without a word. decode says what it waits for and gives up on 4 MiB without a packet; the
// commands that read a recording more than once refuse anything but a file at once.
#include <fcntl.h>
#include <signal.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <string>
#include <thread>

#include <gtest/gtest.h>

#include "cli/cli_run_support.h"
#include "support/raw_recording.h"
#include "support/temp_dir.h"

namespace ydscope {
namespace {

using namespace std::chrono_literals;
using Clock = std::chrono::steady_clock;

constexpr auto kPatience = 20s;  // far beyond any wait the tests cause; a hang fails, not stalls

// ydscope-cli under `timeout`, so a command that blocks fails the test instead of hanging it.
class WaitingInputCli : public ::testing::Test {
 protected:
  void SetUp() override { ASSERT_EQ(::mkfifo(fifo_.c_str(), 0600), 0); }
  test::TempDir dir_{"waiting-input-cli"};
  std::string fifo_ = dir_.file("lidar.fifo");
};

TEST_F(WaitingInputCli, DecodeSaysItWaitsForAFifoAndGoesOnWhenItWrites) {
  const std::string out = dir_.file("out.txt");
  const std::string err = dir_.file("err.txt");
  const pid_t child = ::fork();
  ASSERT_GE(child, 0);
  if (child == 0) {
    ::dup2(::open(out.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0600), STDOUT_FILENO);
    ::dup2(::open(err.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0600), STDERR_FILENO);
    ::execl(YDSCOPE_CLI_PATH, YDSCOPE_CLI_PATH, "decode", "--model", "G6", "--format", "summary", fifo_.c_str(),
            static_cast<char*>(nullptr));
    ::_exit(127);
  }
  const std::string notice = "ydscope-cli decode: waiting for bytes from FIFO " + fifo_ +
                             " (none for 1 s); is the program that writes them running?\n";
  const auto deadline = Clock::now() + kPatience;
  std::string said;
  while (said.find("waiting for bytes") == std::string::npos && Clock::now() < deadline) {
    std::this_thread::sleep_for(20ms);  // polling the condition, bounded by the deadline
    const auto bytes = test::read_file_bytes(err);
    said.assign(bytes.begin(), bytes.end());
  }
  EXPECT_EQ(said, notice);
  // Now the writer comes: decode reads its bytes and ends at its close.
  const int writer = ::open(fifo_.c_str(), O_WRONLY);
  ASSERT_GE(writer, 0);
  EXPECT_EQ(::write(writer, "hello", 5), 5);
  ::close(writer);
  int status = -1;
  while (::waitpid(child, &status, WNOHANG) == 0 && Clock::now() < deadline) std::this_thread::sleep_for(20ms);
  if (Clock::now() >= deadline) ::kill(child, SIGKILL);
  ASSERT_TRUE(WIFEXITED(status)) << "decode did not end after its writer closed the FIFO";
  EXPECT_EQ(WEXITSTATUS(status), 0);
  const auto printed = test::read_file_bytes(out);
  EXPECT_NE(std::string(printed.begin(), printed.end()).find(R"("bytes":5,)"), std::string::npos);
  const auto all_said = test::read_file_bytes(err);
  EXPECT_EQ(std::string(all_said.begin(), all_said.end()),
            notice + "ydscope-cli decode: no complete lap: its bytes are not G6 scan packets\n")
      << "said once per wait";
}

TEST_F(WaitingInputCli, AnInputWithoutAPacketInItsFirst4MiBIsGivenUp) {
  const std::string tail =
      " MiB without one valid G6 scan packet, so decode gave up on it; check that it holds the "
      "bytes of a lidar's port, and the model (--model)\n";
  const auto zero = test::run_cli_bounded("decode --model G6 /dev/zero");
  EXPECT_EQ(zero.status, 1);
  EXPECT_EQ(zero.err, "ydscope-cli decode: /dev/zero gave 4" + tail);
  EXPECT_EQ(zero.out, "");
  const auto piped = test::run_cli_bounded("decode --model G6 - < /dev/zero");
  EXPECT_EQ(piped.status, 1);
  EXPECT_EQ(piped.err, "ydscope-cli decode: standard input gave 4" + tail);
  const auto mcap = test::run_cli_bounded("decode --model G6 --mcap '" + dir_.file("x.mcap") + "' '" + fifo_ + "'");
  EXPECT_EQ(mcap.status, 2);
  EXPECT_EQ(mcap.err, "ydscope-cli decode: --mcap needs a FILE, not standard input, a FIFO or a device\n");
}

TEST_F(WaitingInputCli, CommandsThatReadARecordingTwiceRefuseAFifoAtOnce) {
  const std::string sentence =
      fifo_ +
      " is a FIFO (named pipe), not a file; ydscope reads a recording more than once, so save it to a file "
      "first\n";
  const auto replay = test::run_cli_bounded("replay '" + fifo_ + "'");
  EXPECT_EQ(replay.status, 1);
  EXPECT_EQ(replay.err, "ydscope-cli replay: " + sentence);
  const auto exported = test::run_cli_bounded("export '" + fifo_ + "' --mcap '" + dir_.file("x.mcap") + "'");
  EXPECT_EQ(exported.status, 1);
  EXPECT_EQ(exported.err, "ydscope-cli export: " + sentence);
}

}  // namespace
}  // namespace ydscope
