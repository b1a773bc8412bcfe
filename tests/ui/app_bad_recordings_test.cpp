// Issue 17, in the app: a recording with no device bytes once retried "reconnecting… in 4 s" for
// ever, one with no model (or an unknown one) played silently as G6, a cut-off one gave no
// warning. Now the app says what ydscope-cli replay says, in the same words (both ask
// core/record/recording_plan.h): on stderr and, for a refusal, in the large overlay words.
#include <gtest/gtest.h>
#include <sys/stat.h>

#include <fstream>
#include <iterator>
#include <string>
#include <vector>

#include "app_test_support.h"
#include "core/record/recording_reader.h"
#include "support/program_run.h"
#include "support/raw_recording.h"
#include "test_data.h"

namespace ydscope::test {
namespace {

#ifdef YDSCOPE_APP_PATH

// In the test's folder, with a settings folder of its own.
ProgramRun run_program(const std::filesystem::path& dir, const std::string& program, const std::string& arguments) {
  return test::run_program(program, arguments, {.working_dir = dir.string(), .config_home = dir.string()});
}

// The demo recording's device bytes under other metadata, `late_ns` later than recorded.
RawRecording demo_with_metadata(const std::string& metadata, std::int64_t late_ns = 0) {
  std::string error;
  auto reader = RecordingReader::open((assets_dir() / "demo-g6.ydrec").string(), error);
  EXPECT_TRUE(reader) << error;
  RawRecording recording(1, 16, metadata);
  RecordView record;
  while (reader && reader->next(record))
    if (record.type == RecordType::DeviceToHost)
      recording.add(record.type, record.t_ns + late_ns,
                    std::vector<std::uint8_t>(record.payload.begin(), record.payload.end()));
  return recording;
}

class AppBadRecordings : public testing::Test {
 protected:
  void SetUp() override {
    if (!std::getenv("DISPLAY")) GTEST_SKIP() << "no DISPLAY: run under xvfb-run (scripts/test does)";
    dir_ = fresh_temp_dir("ydscope-bad-recordings");
  }
  void TearDown() override {
    if (!dir_.empty() && !HasFailure() && !std::getenv("YDSCOPE_KEEP_TEST_PNGS")) std::filesystem::remove_all(dir_);
  }
  std::string path(const std::string& name) const { return (dir_ / name).string(); }
  ProgramRun cli_replay(const std::string& file) {
    return run_program(dir_, YDSCOPE_CLI_PATH, "replay '" + file + "' --speed 0 --format summary");
  }
  ProgramRun app(const std::string& arguments, const std::string& png) {
    return run_program(dir_, YDSCOPE_APP_PATH, arguments + " --screenshot '" + path(png) + "' --frames 20");
  }
  // Near-white overlay words in the band where the overlay box writes, at the view's centre.
  int overlay_words(const std::string& png) const {
    const Image image = load_png(path(png));
    EXPECT_TRUE(image) << "no screenshot at " << png;
    if (!image) return 0;
    const int cx = (kViewLeft + image.width) / 2;
    const int cy = image.height / 2;
    return count_pixels(image, {cx - 320, cy - 90, cx + 320, cy + 90}, is_white_pixel);
  }
  int points(const std::string& png) const {
    const Image image = load_png(path(png));
    return image ? points_in_rings(image, kViewLeft) : 0;
  }
  std::filesystem::path dir_;
};

// The sentence ydscope-cli replay printed ("ydscope-cli replay: S\n"), for the app's "ydscope: S\n".
std::string cli_sentence(const ProgramRun& cli) {
  const std::string prefix = "ydscope-cli replay: ";
  EXPECT_EQ(cli.err.rfind(prefix, 0), 0u) << cli.err;
  return cli.err.substr(std::min(prefix.size(), cli.err.size()));
}

TEST_F(AppBadRecordings, NoDeviceBytesIsRefusedInTheCLIsWordsAndOnScreen) {
  const std::string file = path("empty.ydrec");
  RawRecording().write(file);
  const ProgramRun cli = cli_replay(file);
  EXPECT_EQ(cli.status, 1);
  const ProgramRun shown = app("--replay '" + file + "'", "empty.png");
  EXPECT_EQ(shown.status, 1) << shown.err;
  EXPECT_EQ(shown.err.find("reconnecting"), std::string::npos) << shown.err;
  EXPECT_NE(shown.err.find("ydscope: " + cli_sentence(cli)), std::string::npos) << shown.err << "\nCLI: " << cli.err;
  EXPECT_GT(overlay_words("empty.png"), 1500) << "no large overlay words saying why";
}

TEST_F(AppBadRecordings, NoModelOrAnUnknownOneIsRefusedUnlessAModelIsGiven) {
  for (const std::string metadata : {"baud=512000\n", "model=G9\nbaud=512000\n"}) {
    SCOPED_TRACE(metadata);
    const std::string file = path("unnamed.ydrec");
    demo_with_metadata(metadata).write(file);
    const ProgramRun cli = cli_replay(file);
    EXPECT_EQ(cli.status, 2);
    const ProgramRun shown = app("--replay '" + file + "'", "unnamed.png");
    EXPECT_EQ(shown.status, 1) << shown.err;
    EXPECT_NE(shown.err.find("ydscope: " + cli_sentence(cli)), std::string::npos) << shown.err << "\nCLI: " << cli.err;
    EXPECT_GT(overlay_words("unnamed.png"), 1500) << "no large overlay words saying why";
    EXPECT_LT(points("unnamed.png"), 50) << "it was played anyway";
    // What the sentence says to do works in the app too.
    const ProgramRun as_g6 = app("--replay '" + file + "' --model G6", "as-g6.png");
    EXPECT_EQ(as_g6.status, 0) << as_g6.err;
    EXPECT_GT(points("as-g6.png"), 300);
  }
}

TEST_F(AppBadRecordings, ACutOffRecordingPlaysWithTheCLIsWarning) {
  const std::vector<std::uint8_t> demo = read_file_bytes((assets_dir() / "demo-g6.ydrec").string());
  const std::string file = path("cut.ydrec");
  const auto cut = demo.begin() + static_cast<std::ptrdiff_t>(demo.size() / 2 + 7);
  write_file_bytes(file, std::vector<std::uint8_t>(demo.begin(), cut));
  const ProgramRun cli = cli_replay(file);
  ASSERT_EQ(cli.status, 0) << cli.err;
  const std::string warning = cli_sentence(cli);
  EXPECT_EQ(warning.rfind("warning: " + file + " ends inside a record at byte ", 0), 0u) << warning;
  const ProgramRun shown = app("--replay '" + file + "'", "cut.png");
  EXPECT_EQ(shown.status, 0) << shown.err;
  EXPECT_NE(shown.err.find("ydscope: " + warning), std::string::npos) << shown.err << "\nCLI: " << cli.err;
  EXPECT_GT(points("cut.png"), 300) << "what is intact must still play";
}

TEST_F(AppBadRecordings, BytesWithoutALapGiveUpAfterOnePass) {
  RawRecording junk;  // model G6; 40 records of one byte each, 25 ms apart: no scan packet
  std::vector<std::int64_t> times;
  for (int i = 0; i < 40; ++i) times.push_back(i * 25'000'000LL);
  junk.add_device_records(times);
  const std::string file = path("junk.ydrec");
  junk.write(file);
  const ProgramRun shown = app("--replay '" + file + "'", "junk.png");
  EXPECT_EQ(shown.status, 1) << shown.err;
  EXPECT_NE(shown.err.find("ydscope: recording junk.ydrec played through without one complete lap; its bytes are not "
                           "G6 scan packets"),
            std::string::npos)
      << shown.err;
  EXPECT_GT(overlay_words("junk.png"), 1500) << "no large overlay words saying why";
}

// Issue 26: corrupt before its model record, or a FIFO nobody writes to (which once blocked the
// app without a word): refused at once in the CLI's words.
TEST_F(AppBadRecordings, DamageBeforeTheModelAndAFifoAreRefusedInTheCLIsWords) {
  RawRecording commands(1, 16, "port=/dev/pts/1\n");
  commands.add(RecordType::HostToDevice, 1000, {0xA5, 0x90});
  std::vector<std::uint8_t> bytes = commands.bytes();
  bytes.insert(bytes.end(), {1, 0, 0, 0, 0xFF, 0xFF, 0xFF, 0xFF, 0, 0, 0, 0, 0, 0, 0, 0});
  write_file_bytes(path("corrupt.ydrec"), bytes);
  const std::string fifo = path("lidar.fifo");
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
  for (const std::string& file : {path("corrupt.ydrec"), fifo}) {
    const ProgramRun cli = cli_replay(file);
    EXPECT_EQ(cli.status, 1) << cli.err;
    const ProgramRun shown = app("--replay '" + file + "'", "refused.png");
    EXPECT_EQ(shown.status, 1) << shown.err;
    EXPECT_NE(shown.err.find("ydscope: " + cli_sentence(cli)), std::string::npos) << shown.err << "\nCLI: " << cli.err;
    EXPECT_GT(overlay_words("refused.png"), 1500) << "no large overlay words saying why";
  }
}

// Issue 26: a legal gap (59 s) froze the replay without a word. The app says it and plays on.
TEST_F(AppBadRecordings, ALongGapIsSaidAndSkipped) {
  const std::string file = path("late.ydrec");
  demo_with_metadata("model=G6\n", 59'000'000'000).write(file);  // the demo's bytes, a minute late
  const ProgramRun shown = app("--replay '" + file + "'", "late.png");
  EXPECT_EQ(shown.status, 0) << shown.err;
  EXPECT_NE(shown.err.find("ydscope: the recording has a gap of 59.0 s at 0.0 s without a byte from the lidar; "
                           "skipped to 59.0 s\n"),
            std::string::npos)
      << shown.err;
  EXPECT_GT(points("late.png"), 300) << "waited the gap out instead of skipping it";
}

#endif

}  // namespace
}  // namespace ydscope::test
