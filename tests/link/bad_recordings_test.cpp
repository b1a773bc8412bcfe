// Damaged and hostile recordings (issue 17): record times that go back or jump, file headers that
// lie, replay speeds at the edge of what doubles hold. None may hang, spin or pass silently.
#include <unistd.h>

#include <cstdint>
#include <filesystem>
#include <functional>
#include <limits>
#include <string>
#include <vector>

#include <boost/asio/io_context.hpp>
#include <gtest/gtest.h>

#include "core/link/replay_link.h"
#include "core/record/recording_reader.h"
#include "link/link_read_support.h"
#include "support/raw_recording.h"
#include "support/temp_dir.h"

namespace ydscope {
namespace {

namespace fs = std::filesystem;
using Bytes = std::vector<std::uint8_t>;
using test::RawRecording;
constexpr std::int64_t kMs = 1'000'000;
constexpr std::int64_t kInt64Min = std::numeric_limits<std::int64_t>::min();

class BadRecordings : public ::testing::Test {
 protected:
  std::string write(const std::string& name, const Bytes& bytes) const {
    const std::string file = dir_.file(name);
    test::write_file_bytes(file, bytes);
    return file;
  }
  // The times of the device records, as the reader hands them out.
  static std::vector<std::int64_t> device_times(RecordingReader& reader) {
    std::vector<std::int64_t> times;
    RecordView record;
    while (reader.next(record))
      if (record.type == RecordType::DeviceToHost) times.push_back(record.t_ns);
    return times;
  }

  test::TempDir dir_{"bad-recordings"};
};

TEST_F(BadRecordings, SoundTimesAreReadAsWrittenWithoutAWarning) {
  RawRecording recording;
  recording.add_device_records({0, 1 * kMs, 1 * kMs, 5 * kMs, 5 * kMs + kMaxRecordGapNs});
  std::string error;
  auto reader = RecordingReader::open(write("a.ydrec", recording.bytes()), error);
  ASSERT_TRUE(reader) << error;
  EXPECT_EQ(device_times(*reader),
            (std::vector<std::int64_t>{0, 1 * kMs, 1 * kMs, 5 * kMs, 5 * kMs + kMaxRecordGapNs}));
  EXPECT_EQ(reader->time_corrections(), 0u);
  EXPECT_EQ(reader->time_warning(), "");
}

TEST_F(BadRecordings, ATimeThatGoesBackIsReadAsThePreviousOne) {
  RawRecording recording;
  recording.add_device_records({1 * kMs, 2 * kMs, kInt64Min, 3 * kMs, 4 * kMs});
  const std::string file = write("back.ydrec", recording.bytes());
  std::string error;
  auto reader = RecordingReader::open(file, error);
  ASSERT_TRUE(reader) << error;
  // INT64_MIN is read as 2 ms; the record after it (3 ms in the file's own timeline, far ahead
  // of INT64_MIN) is damage too and plays at once; then the spacing of the file resumes.
  EXPECT_EQ(device_times(*reader), (std::vector<std::int64_t>{1 * kMs, 2 * kMs, 2 * kMs, 2 * kMs, 3 * kMs}));
  EXPECT_EQ(reader->time_corrections(), 2u);
  EXPECT_EQ(reader->time_warning(), file +
                                        " has damaged record times: the record at byte 75 goes back 9.22e+09 s "
                                        "in time (2 such records); each plays right after the record before it, "
                                        "and the ones after keep their spacing");
  // Rewinding starts the check over: the same times the second time through.
  reader->rewind();
  EXPECT_EQ(device_times(*reader), (std::vector<std::int64_t>{1 * kMs, 2 * kMs, 2 * kMs, 2 * kMs, 3 * kMs}));
}

TEST_F(BadRecordings, AJumpShiftsTheRestOfTheRecordingBackInPlace) {
  RawRecording recording;
  constexpr std::int64_t kFar = 1'000'000'000'000'000'000;  // 31 years
  recording.add_device_records({1 * kMs, 2 * kMs, kFar, kFar + 1 * kMs, kFar + 3 * kMs});
  const std::string file = write("jump.ydrec", recording.bytes());
  std::string error;
  const auto summary = summarize_recording(file, error);
  ASSERT_TRUE(summary) << error;
  EXPECT_EQ(summary->duration_ns, 5 * kMs);
  EXPECT_EQ(summary->time_warning, file +
                                       " has damaged record times: the record at byte 75 jumps 1e+09 s ahead "
                                       "(more than 60 s); each plays right after the record before it, and the "
                                       "ones after keep their spacing");
  auto reader = RecordingReader::open(file, error);
  ASSERT_TRUE(reader) << error;
  EXPECT_EQ(device_times(*reader), (std::vector<std::int64_t>{1 * kMs, 2 * kMs, 2 * kMs, 3 * kMs, 5 * kMs}));
}

TEST_F(BadRecordings, ExtremeTimesAtEitherEndNeverOverflow) {
  RawRecording recording;
  constexpr std::int64_t kMax = std::numeric_limits<std::int64_t>::max();
  recording.add_device_records({kMax, kInt64Min, kMax, 0, kInt64Min + 1, -1});
  std::string error;
  auto reader = RecordingReader::open(write("edges.ydrec", recording.bytes()), error);
  ASSERT_TRUE(reader) << error;
  const auto times = device_times(*reader);
  ASSERT_EQ(times.size(), 6u);
  for (std::size_t i = 1; i < times.size(); ++i) {
    EXPECT_GE(times[i], times[i - 1]);
    EXPECT_LE(times[i] - times[i - 1], kMaxRecordGapNs);
  }
  EXPECT_EQ(times.front(), 0);
  EXPECT_GT(reader->time_corrections(), 0u);
}

// After a rewind an early metadata record must neither undo a later one nor repeat its warnings.
TEST_F(BadRecordings, MetadataIsMergedOnceWhateverTheRewinds) {
  RawRecording recording(1, 16, "model=G6\nbaud=fast\n");
  recording.add_device_records({1 * kMs});
  const std::string later = "model=TG30\n";
  recording.add(RecordType::Metadata, 2 * kMs, Bytes(later.begin(), later.end()));
  std::string error;
  auto reader = RecordingReader::open(write("meta.ydrec", recording.bytes()), error);
  ASSERT_TRUE(reader) << error;
  for (int pass = 0; pass < 3; ++pass) {
    device_times(*reader);
    EXPECT_EQ(reader->metadata().model, "TG30") << "pass " << pass;
    EXPECT_EQ(reader->metadata_warnings().size(), 1u) << "pass " << pass;
    reader->rewind();
  }
}

// Each kind of bad header is named for what it is, and a version or header size this ydscope
// cannot read is Unsupported (the CLI's exit 2), not "not a recording".
TEST_F(BadRecordings, HeadersSayWhatIsReallyWrong) {
  struct Case {
    std::string name;
    Bytes bytes;
    RecordingOpenFailure failure;
    std::string sentence;  // after the path
  };
  RawRecording sound;
  sound.add_device_records({1 * kMs});
  const Bytes& whole = sound.bytes();
  RawRecording size_ffff(1, 0xFFFF);
  RawRecording size_4(1, 4);
  RawRecording version_0(0, 16);
  RawRecording version_7(7, 16);
  const std::vector<Case> cases{
      {"empty", {}, RecordingOpenFailure::NotARecording, " is empty, not a ydscope recording"},
      {"raw",
       {0xAA, 0x55, 0x01, 0x01},
       RecordingOpenFailure::NotARecording,
       " is not a ydscope recording (no YDSCOPE-REC header)"},
      {"cut15", Bytes(whole.begin(), whole.begin() + 15), RecordingOpenFailure::NotARecording,
       " ends after 15 bytes, inside its 16-byte file header: the recording was cut off before anything was recorded"},
      {"cut5", Bytes(whole.begin(), whole.begin() + 5), RecordingOpenFailure::NotARecording,
       " ends after 5 bytes, inside its 16-byte file header: the recording was cut off before anything was recorded"},
      {"size4", size_4.bytes(), RecordingOpenFailure::Unsupported,
       " has an impossible file-header size of 4 bytes (version 1 writes 16): the file is damaged"},
      {"sizeffff", size_ffff.bytes(), RecordingOpenFailure::Unsupported,
       " has an impossible file-header size of 65535 bytes in a 41-byte file (version 1 writes 16): the file is "
       "damaged"},
      {"version0", version_0.bytes(), RecordingOpenFailure::Unsupported,
       " says it is a version 0 recording, which does not exist (this ydscope reads versions 1 and 2): the file is "
       "damaged"},
      {"version7", version_7.bytes(), RecordingOpenFailure::Unsupported,
       " is a version 7 recording; this ydscope reads versions 1 and 2, update ydscope"},
  };
  for (const Case& c : cases) {
    const std::string file = write(c.name + ".ydrec", c.bytes);
    std::string error;
    auto failure = RecordingOpenFailure::Unreadable;
    EXPECT_FALSE(RecordingReader::open(file, error, &failure)) << c.name;
    EXPECT_EQ(error, file + c.sentence) << c.name;
    EXPECT_EQ(failure, c.failure) << c.name;
  }
  std::string error;
  auto failure = RecordingOpenFailure::NotARecording;
  EXPECT_FALSE(RecordingReader::open(dir_.string(), error, &failure));
  EXPECT_EQ(error, dir_.string() + " is a folder; pass a recording file (.ydrec) instead");
  EXPECT_EQ(failure, RecordingOpenFailure::Unreadable);
  // The sound one opens, and so does a header that leaves room for later fields.
  EXPECT_TRUE(RecordingReader::open(write("sound.ydrec", whole), error)) << error;
}

TEST(ReplaySpeed, IsBoundedToWhatMakesSense) {
  EXPECT_EQ(bounded_replay_speed(1.0), 1.0);
  EXPECT_EQ(bounded_replay_speed(0.0), 0.0);
  EXPECT_EQ(bounded_replay_speed(-3.0), 0.0);
  EXPECT_EQ(bounded_replay_speed(1e-300), kMinReplaySpeed);
  EXPECT_EQ(bounded_replay_speed(1e-10), kMinReplaySpeed);
  EXPECT_EQ(bounded_replay_speed(1e300), kMaxReplaySpeed);
  EXPECT_EQ(bounded_replay_speed(std::numeric_limits<double>::infinity()), kMaxReplaySpeed);
  EXPECT_EQ(bounded_replay_speed(std::numeric_limits<double>::quiet_NaN()), 1.0);
}

// speed 1e-300 once made `ahead / speed` overflow to a negative wait: the timer fired again and
// again at 97 % of a core, forever. Counting the handlers the io_context ran shows a spin
// without timing anything: a waiting replay runs a handful, the spin ran thousands.
TEST_F(BadRecordings, ATinySpeedWaitsInsteadOfSpinning) {
  RawRecording recording;
  recording.add_device_records({0, 1'000 * kMs});  // a second apart
  const std::string file = write("slow.ydrec", recording.bytes());
  for (const double speed : {1e-300, 1e-10}) {
    boost::asio::io_context io;
    std::string error;
    auto link = ReplayLink::open(io, file, {.speed = speed}, error);
    ASSERT_TRUE(link) << error;
    EXPECT_EQ(link->status().speed, kMinReplaySpeed);
    std::vector<std::uint8_t> buffer(16);
    int reads = 0;
    std::function<void()> read = [&] {
      link->async_read_some(buffer, [&](const boost::system::error_code& ec, std::size_t) {
        if (ec) return;
        if (++reads < 2) read();
      });
    };
    read();
    const std::size_t handlers = io.run_for(std::chrono::milliseconds(200));
    EXPECT_EQ(reads, 1) << "the second record is 1000 s of playback away at speed " << speed;
    EXPECT_LT(handlers, 20u) << "speed " << speed;
    link->close();
    io.restart();
    io.poll();
  }
}

// INT64_MIN once was signed overflow (and a silent hang), 1e18 a 31-year wait: both play to the
// end at the recorded speed, promptly.
TEST_F(BadRecordings, DamagedTimesPlayToTheEndAtRecordedSpeed) {
  for (const std::int64_t damage : {kInt64Min, std::int64_t{1'000'000'000'000'000'000}}) {
    RawRecording recording;
    recording.add_device_records({1 * kMs, 2 * kMs, damage, 3 * kMs, 4 * kMs});
    const std::string file = write("damaged.ydrec", recording.bytes());
    boost::asio::io_context io;
    std::string error;
    auto link = ReplayLink::open(io, file, {.speed = 1.0}, error);
    ASSERT_TRUE(link) << error;
    ASSERT_EQ(link->warnings().size(), 1u);
    EXPECT_NE(link->warnings()[0].find("has damaged record times"), std::string::npos) << link->warnings()[0];
    const auto result = test::read_from_link(io, *link, SIZE_MAX, 16, std::chrono::seconds(10));
    EXPECT_EQ(result.bytes, (Bytes{0, 1, 2, 3, 4})) << "damage " << damage;
    EXPECT_EQ(result.end, boost::asio::error::eof) << "damage " << damage;
  }
}

}  // namespace
}  // namespace ydscope
