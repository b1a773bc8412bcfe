// ydscope-cli given damaged recordings and odd options (issue 17), as a user would run it: one
// sentence that says what is really wrong and the documented exit status, or a warning and the
// laps; never a hang, never invalid JSON.
#include <unistd.h>

#include <algorithm>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <limits>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "core/record/recording_reader.h"
#include "cli/cli_run_support.h"
#include "support/raw_recording.h"
#include "test_data.h"
#include "support/temp_dir.h"

namespace ydscope {
namespace {

namespace fs = std::filesystem;
using Bytes = std::vector<std::uint8_t>;
using test::RawRecording;
using test::run_cli_apart;

std::string demo_recording() { return (test::assets_dir() / "demo-g6.ydrec").string(); }

class BadInputCli : public ::testing::Test {
 protected:
  std::string path(const std::string& name) const { return dir_.file(name); }

  // The demo recording with the time field of every record from the `first`-th on rewritten.
  std::string demo_with_times(const std::string& name, std::size_t first,
                              std::int64_t (*rewrite)(std::int64_t t_ns, std::size_t index)) const {
    Bytes bytes = test::read_file_bytes(demo_recording());
    std::string error;
    auto reader = RecordingReader::open(demo_recording(), error);
    EXPECT_TRUE(reader) << error;
    RecordView record;
    for (std::size_t index = 0; reader && reader->next(record); ++index) {
      if (index < first) continue;
      const std::int64_t t_ns = rewrite(record.t_ns, index - first);
      std::memcpy(bytes.data() + record.file_offset + 8, &t_ns, sizeof t_ns);  // little-endian host
    }
    const std::string file = path(name);
    test::write_file_bytes(file, bytes);
    return file;
  }
  static std::size_t lines(const std::string& text) {
    return static_cast<std::size_t>(std::count(text.begin(), text.end(), '\n'));
  }

  test::TempDir dir_{"bad-input-cli"};
};

TEST_F(BadInputCli, ReplaySpeedOutsideItsRangeIsAUsageError) {
  for (const std::string speed : {"1e-300", "1e-10", "0.0009", "-1", "nan", "1e7"}) {
    const auto run = run_cli_apart("replay '" + demo_recording() + "' --speed " + speed);
    EXPECT_EQ(run.status, 2) << speed;
    EXPECT_EQ(lines(run.err), 1u) << run.err;
    EXPECT_NE(run.err.find("--speed must be"), std::string::npos) << run.err;
    EXPECT_EQ(run.out, "") << speed;
  }
  EXPECT_EQ(run_cli_apart("replay '" + demo_recording() + "' --speed 1e-300").err,
            "ydscope-cli replay: --speed must be 0 (as fast as possible) or from 0.001 to 1000000, not '1e-300'\n");
}

// A record at INT64_MIN (once undefined behaviour and a hang), and the rest of the recording
// shifted 1e18 ns ahead (once a 31-year wait): both play to the end, with the laps a sound file
// gives and a warning.
TEST_F(BadInputCli, DamagedTimesPlayToTheEndWithAWarning) {
  const auto sound = run_cli_apart("decode --format summary '" + demo_recording() + "'");
  ASSERT_EQ(sound.status, 0) << sound.err;
  const std::string back = demo_with_times("back.ydrec", 200, [](std::int64_t t, std::size_t i) {
    return i == 0 ? std::numeric_limits<std::int64_t>::min() : t;
  });
  const std::string ahead =
      demo_with_times("ahead.ydrec", 200, [](std::int64_t t, std::size_t) { return t + 1'000'000'000'000'000'000; });
  for (const std::string& file : {back, ahead}) {
    const auto run = run_cli_apart("replay --speed 100 --format summary '" + file + "'");
    EXPECT_EQ(run.status, 0) << run.err;
    EXPECT_EQ(run.out, sound.out) << file;
    EXPECT_EQ(lines(run.err), 1u) << run.err;
    EXPECT_NE(run.err.find("ydscope-cli replay: warning: " + file + " has damaged record times: the record at byte "),
              std::string::npos)
        << run.err;
  }
}

TEST_F(BadInputCli, RecordingsThisYdscopeCannotReadAreAUsageError) {
  RawRecording(0, 16).write(path("v0.ydrec"));
  RawRecording(1, 0xFFFF).write(path("hffff.ydrec"));
  RawRecording(1, 4).write(path("h4.ydrec"));
  for (const std::string name : {"v0.ydrec", "hffff.ydrec", "h4.ydrec"}) {
    for (const std::string command : {"replay", "decode"}) {
      const auto run = run_cli_apart(command + " '" + path(name) + "'");
      EXPECT_EQ(run.status, 2) << command << " " << name << ": " << run.err;
      EXPECT_EQ(lines(run.err), 1u) << run.err;
      EXPECT_NE(run.err.find("the file is damaged"), std::string::npos) << run.err;
      EXPECT_EQ(run.out, "");
    }
  }
  // Cut inside the header: the magic is there, so it is not "not a recording".
  const Bytes demo = test::read_file_bytes(demo_recording());
  test::write_file_bytes(path("cut.ydrec"), Bytes(demo.begin(), demo.begin() + 15));
  const auto cut = run_cli_apart("replay '" + path("cut.ydrec") + "'");
  EXPECT_EQ(cut.status, 1);
  EXPECT_EQ(cut.err, "ydscope-cli replay: " + path("cut.ydrec") +
                         " ends after 15 bytes, inside its 16-byte file header: the recording was cut off before "
                         "anything was recorded\n");
  const auto folder = run_cli_apart("replay '" + dir_.string() + "'");
  EXPECT_EQ(folder.status, 1);
  EXPECT_EQ(folder.err,
            "ydscope-cli replay: " + dir_.string() + " is a folder; pass a recording file (.ydrec) instead\n");
}

// A recording's distance_scale once went unchecked into replay ("points":[[nan,nan,0],...) and
// was ignored by decode, so the two disagreed on the same file.
TEST_F(BadInputCli, RecordedDistanceScaleIsCheckedAndTheSameInDecodeAndReplay) {
  std::string error;
  auto demo = RecordingReader::open(demo_recording(), error);
  ASSERT_TRUE(demo) << error;
  const auto with_scale = [&](const std::string& name, const std::string& scale) {
    // The demo's start too, so the summaries agree on it as they must on the laps.
    RawRecording recording(1, 16,
                           "model=G6\ndistance_scale=" + scale +
                               "\nstart_wall_time=" + demo->metadata().start_wall_time.value_or("") + "\n");
    demo->rewind();
    RecordView record;
    while (demo->next(record))
      if (record.type == RecordType::DeviceToHost)
        recording.add(record.type, record.t_ns, Bytes(record.payload.begin(), record.payload.end()));
    recording.write(path(name));
    return path(name);
  };
  const auto plain = run_cli_apart("decode '" + demo_recording() + "'");  // the demo records the manual's 0.25
  ASSERT_EQ(plain.status, 0) << plain.err;
  for (const std::string bad : {"nan", "inf", "1e300", "-1", "0"}) {
    const std::string file = with_scale("bad.ydrec", bad);
    const auto decoded = run_cli_apart("decode '" + file + "'");
    const auto replayed = run_cli_apart("replay --speed 0 '" + file + "'");
    EXPECT_EQ(decoded.status, 0) << decoded.err;
    EXPECT_EQ(replayed.status, 0) << replayed.err;
    EXPECT_EQ(decoded.out, plain.out) << bad << ": the model's own scale";
    EXPECT_EQ(replayed.out, plain.out) << bad;
    for (const auto* run : {&decoded, &replayed}) {
      EXPECT_EQ(lines(run->err), 1u) << run->err;
      EXPECT_NE(run->err.find(file + ": metadata distance_scale='" + bad + "' is not a number from 1e-06 to 1e+06"),
                std::string::npos)
          << run->err;
    }
  }
  const std::string doubled = with_scale("half.ydrec", "0.5");
  const auto decoded = run_cli_apart("decode '" + doubled + "'");
  EXPECT_EQ(decoded.err, "");
  EXPECT_NE(decoded.out, plain.out);
  EXPECT_EQ(decoded.out, run_cli_apart("replay --speed 0 '" + doubled + "'").out);
  EXPECT_EQ(decoded.out, run_cli_apart("decode --model G6 --distance-scale 0.5 '" + demo_recording() + "'").out);
}

// record --out /dev/null once recorded for a second and then failed with "/dev/null is not a
// ydscope recording": the output is checked before anything connects (the port here does not
// exist, so any other failure would name it).
TEST_F(BadInputCli, RecordChecksItsOutputBeforeStarting) {
  const std::string port = "/dev/ttyDOESNOTEXIST9";
  struct Case {
    std::string out;
    std::string sentence;
  };
  const std::vector<Case> cases{
      {"/dev/null",
       "cannot record to /dev/null: it is not a regular file (a device or a pipe), and a recording must "
       "be read back; give a file name such as bench.ydrec"},
      {dir_.string(), "cannot record to " + dir_.string() + ": it is a folder; give a file name such as " +
                          (dir_ / "bench.ydrec").string()},
      {path("missing/x.ydrec"), "cannot record to " + path("missing/x.ydrec") + ": the folder " + path("missing") +
                                    " does not exist; create it or choose another"},
  };
  for (const Case& c : cases) {
    for (const std::string force : {"", " --force"}) {
      const auto run = run_cli_apart("record --port " + port + " --out '" + c.out + "'" + force);
      EXPECT_EQ(run.status, 2) << c.out << force;
      EXPECT_EQ(run.err, "ydscope-cli record: " + c.sentence + "\n") << force;
      EXPECT_EQ(run.out, "");
    }
  }
  EXPECT_FALSE(fs::exists(path("missing")));
}

// Issue 26: corrupt before its model record, decode and export said "does not say which lidar made
// it; pass --model" and replay "holds no bytes from a device": each now names the corruption.
TEST_F(BadInputCli, ACorruptionBeforeTheModelIsWhatEveryCommandSays) {
  RawRecording head(1, 16, "port=/dev/pts/1\n");
  head.add(RecordType::HostToDevice, 1000, {0xA5, 0x90});
  Bytes bytes = head.bytes();
  const std::size_t at = bytes.size();
  bytes.insert(bytes.end(), {1, 0, 0, 0, 0xFF, 0xFF, 0xFF, 0xFF, 0, 0, 0, 0, 0, 0, 0, 0});
  const std::string file = path("corrupt.ydrec");
  test::write_file_bytes(file, bytes);
  const std::string cause =
      file + " is corrupt at byte " + std::to_string(at) +
      " (record type 1, length 4294967295); the 2 records before it are intact, and none of them ";
  const std::pair<std::string, std::string> cases[] = {
      {"decode", "says which lidar made it: nothing to decode"},
      {"replay", "holds bytes from a device: nothing to replay"},
      {"export", "says which lidar made it: nothing to decode"},
  };
  for (const auto& [command, ending] : cases) {
    const auto run =
        run_cli_apart(command + " '" + file + "'" + (command == "export" ? " --mcap '" + path("o.mcap") + "'" : ""));
    EXPECT_EQ(run.status, 1) << command << ": " << run.err;
    EXPECT_EQ(run.err, "ydscope-cli " + command + ": " + cause + ending + "\n");
    EXPECT_EQ(run.out, "");
  }
  EXPECT_FALSE(fs::exists(path("o.mcap")));
}

// Issue 26: a warning quoting metadata copied its bytes to the terminal (ESC sequences included).
TEST_F(BadInputCli, MetadataQuotedOnStderrCannotDriveTheTerminal) {
  const std::string esc = "\x1b]0;owned\x07\x1b[2J";
  RawRecording bad_baud(1, 16, "model=G6\nbaud=" + esc + "\n");
  bad_baud.add_device_records({0});
  bad_baud.write(path("baud.ydrec"));
  RawRecording bad_model(1, 16, "model=" + esc + "\n");
  bad_model.add_device_records({0});
  bad_model.write(path("model.ydrec"));
  const std::string shown = "'\\x1b]0;owned\\x07\\x1b[2J'";
  for (const std::string command : {"decode", "replay --speed 0"}) {
    const auto warned = run_cli_apart(command + " --format summary '" + path("baud.ydrec") + "'");
    EXPECT_EQ(warned.status, 0) << warned.err;
    EXPECT_NE(warned.err.find("metadata baud=" + shown + " is not a whole number"), std::string::npos) << warned.err;
    const auto refused = run_cli_apart(command + " '" + path("model.ydrec") + "'");
    EXPECT_EQ(refused.status, 2) << refused.err;
    EXPECT_NE(refused.err.find("was made with model " + shown + ", which"), std::string::npos) << refused.err;
    for (const auto* run : {&warned, &refused}) {
      EXPECT_EQ(run->err.find('\x1b'), std::string::npos) << command;
      EXPECT_EQ(run->err.find('\x07'), std::string::npos) << command;
    }
  }
}

// info, scan and set said 1 for a port that is not there, record's help 2, and serve waited for
// it forever: every command that opens a port now says the same sentence, with the help's 2.
TEST_F(BadInputCli, AMissingPortIsAUsageErrorFromEveryCommand) {
  const std::string port = "/dev/ttyNOPE";
  const std::string out = " --out '" + path("never.ydrec") + "'";
  const std::vector<std::string> commands{
      "info", "scan --laps 1", "set --scan-hz 8", "check --seconds 1", "record --seconds 1" + out, "serve --seconds 1"};
  for (const std::string& command : commands) {
    const std::string name = command.substr(0, command.find(' '));
    const auto run = run_cli_apart(command + " --port " + port + " </dev/null");
    EXPECT_EQ(run.status, 2) << command << ": " << run.err;
    EXPECT_EQ(run.err, "ydscope-cli " + name + ": there is no port " + port +
                           "; is the lidar plugged in? `ydscope-cli ports` lists the ones attached\n")
        << command;
    EXPECT_EQ(run.out, "") << command;
    const auto help = run_cli_apart(name + " --help");
    EXPECT_NE(help.out.find("a port that does not exist"), std::string::npos) << name;
  }
  EXPECT_FALSE(fs::exists(path("never.ydrec")));
}

// decode without --model once said "missing required option --model" for these.
TEST_F(BadInputCli, DecodeChecksTheFileBeforeAskingForAModel) {
  auto run = run_cli_apart("decode '" + dir_.string() + "'");
  EXPECT_EQ(run.status, 1);
  EXPECT_EQ(run.err, "ydscope-cli decode: '" + dir_.string() + "' is a folder; pass a file or - for standard input\n");
  run = run_cli_apart("decode '" + path("missing.bin") + "'");
  EXPECT_EQ(run.status, 2);
  EXPECT_EQ(run.err, "ydscope-cli decode: input file '" + path("missing.bin") + "' was not found; check the path\n");
  // A readable raw file still needs the model.
  test::write_file_bytes(path("raw.bin"), {0xAA, 0x55});
  run = run_cli_apart("decode '" + path("raw.bin") + "'");
  EXPECT_EQ(run.status, 2);
  EXPECT_NE(run.err.find("missing required option --model"), std::string::npos) << run.err;
}

}  // namespace
}  // namespace ydscope
