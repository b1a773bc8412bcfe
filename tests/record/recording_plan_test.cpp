// The one place that says what a recording can be decoded or played as (core/record/
// recording_plan.h), asked by ydscope-cli and by the app alike: its sentences, its kinds, and
// the damage it reports as warnings.
#include <gtest/gtest.h>
#include <sys/stat.h>
#include <unistd.h>

#include <filesystem>
#include <string>
#include <vector>

#include "core/record/recording_plan.h"
#include "support/raw_recording.h"

namespace ydscope {
namespace {

using test::RawRecording;

class RecordingPlanTest : public testing::Test {
 protected:
  void SetUp() override {
    dir_ = std::filesystem::path(testing::TempDir()) / ("ydscope-plan-" + std::to_string(::getpid()));
    std::filesystem::create_directories(dir_);
  }
  void TearDown() override { std::filesystem::remove_all(dir_); }
  std::string write(const std::string& name, const RawRecording& recording) {
    const std::string path = (dir_ / name).string();
    recording.write(path);
    return path;
  }
  std::filesystem::path dir_;
};

const std::string kModels = "G1, G6, TG15, TG30, TG50";

TEST_F(RecordingPlanTest, ARecordingWithDeviceBytesPlaysAsItsModelAndScale) {
  RawRecording recording(1, 16, "model=TG30\ndistance_scale=1\n");
  recording.add_device_records({0, 1000});
  const std::string path = write("tg30.ydrec", recording);
  const RecordingPlan plan = plan_recording(path, RecordingUse::Replay, std::nullopt, std::nullopt);
  ASSERT_TRUE(plan.usable()) << plan.refusal_text;
  EXPECT_EQ(plan.profile->model, Model::TG30);
  EXPECT_EQ(plan.distance_scale, 1.0);
  EXPECT_TRUE(plan.warnings().empty());
  // Another model drops the recorded scale (it belonged to the recorded model); a chosen scale wins.
  const RecordingPlan as_g6 = plan_recording(path, RecordingUse::Replay, "G6", std::nullopt);
  EXPECT_EQ(as_g6.profile->model, Model::G6);
  EXPECT_FALSE(as_g6.distance_scale.has_value());
  EXPECT_EQ(plan_recording(path, RecordingUse::Replay, "G6", 0.5).distance_scale, 0.5);
}

// Issue 17: in the app such a file retried "reconnecting… in 4 s" for ever.
TEST_F(RecordingPlanTest, NoDeviceBytesIsNothingToReplayButDecodesToNoLaps) {
  const std::string path = write("empty.ydrec", RawRecording());
  const RecordingPlan replay = plan_recording(path, RecordingUse::Replay, std::nullopt, std::nullopt);
  EXPECT_EQ(replay.refusal, RecordingRefusal::NothingToPlay);
  EXPECT_EQ(replay.refusal_text, path + " holds no bytes from a device; nothing to replay");
  EXPECT_TRUE(plan_recording(path, RecordingUse::Decode, std::nullopt, std::nullopt).usable());
}

// Issue 17: the app once played these silently as G6.
TEST_F(RecordingPlanTest, NoModelOrAnUnknownOneNeedsAModel) {
  RawRecording anonymous(1, 16, "baud=512000\n");
  anonymous.add_device_records({0});
  const std::string nameless = write("nameless.ydrec", anonymous);
  RecordingPlan plan = plan_recording(nameless, RecordingUse::Replay, std::nullopt, std::nullopt);
  EXPECT_EQ(plan.refusal, RecordingRefusal::NeedsModel);
  EXPECT_EQ(plan.refusal_text, nameless + " does not say which lidar made it; pass --model (" + kModels + ")");
  EXPECT_TRUE(plan_recording(nameless, RecordingUse::Replay, "G1", std::nullopt).usable());

  RawRecording g9(1, 16, "model=G9\n");
  g9.add_device_records({0});
  const std::string unknown = write("g9.ydrec", g9);
  plan = plan_recording(unknown, RecordingUse::Decode, std::nullopt, std::nullopt);
  EXPECT_EQ(plan.refusal, RecordingRefusal::NeedsModel);
  EXPECT_EQ(plan.refusal_text,
            unknown + " was made with model 'G9', which this ydscope does not know; pass --model (" + kModels + ")");
  plan = plan_recording(unknown, RecordingUse::Decode, "G7", std::nullopt);
  EXPECT_EQ(plan.refusal_text, "unknown model 'G7'; valid models are " + kModels);
}

TEST_F(RecordingPlanTest, OpenFailuresKeepTheirKindAndSentence) {
  RecordingPlan plan = plan_recording((dir_ / "none.ydrec").string(), RecordingUse::Replay, std::nullopt, std::nullopt);
  EXPECT_EQ(plan.refusal, RecordingRefusal::Unreadable);
  EXPECT_FALSE(plan.refusal_text.empty());
  RawRecording version9(9);
  plan = plan_recording(write("v9.ydrec", version9), RecordingUse::Replay, std::nullopt, std::nullopt);
  EXPECT_EQ(plan.refusal, RecordingRefusal::Unsupported);
  EXPECT_NE(plan.refusal_text.find("version 9"), std::string::npos) << plan.refusal_text;
}

// The CLI warns about these; the app says the same words beside its status line.
TEST_F(RecordingPlanTest, DamageThatStillPlaysIsAWarningEach) {
  RawRecording recording;
  recording.add_device_records({0, 1000, 2000});
  std::vector<std::uint8_t> bytes = recording.bytes();
  bytes.resize(bytes.size() - 1);  // cut inside the last record
  const std::string path = (dir_ / "cut.ydrec").string();
  test::write_file_bytes(path, bytes);
  const RecordingPlan plan = plan_recording(path, RecordingUse::Replay, std::nullopt, std::nullopt);
  ASSERT_TRUE(plan.usable()) << plan.refusal_text;
  ASSERT_EQ(plan.warnings().size(), 1u);
  EXPECT_EQ(plan.warnings()[0].rfind(path + " ends inside a record at byte ", 0), 0u) << plan.warnings()[0];
  EXPECT_NE(plan.warnings()[0].find("the 3 records before it are intact"), std::string::npos) << plan.warnings()[0];
}

// Issue 26: a FIFO nobody writes to blocked replay, export and the app without a word. A recording
// is read more than once, so anything but a file is refused at once, and never opened.
TEST_F(RecordingPlanTest, AFifoOrADeviceIsRefusedWithoutWaitingForIt) {
  const std::string fifo = (dir_ / "lidar.fifo").string();
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
  for (const RecordingUse use : {RecordingUse::Decode, RecordingUse::Replay}) {
    const RecordingPlan plan = plan_recording(fifo, use, std::nullopt, std::nullopt);
    EXPECT_EQ(plan.refusal, RecordingRefusal::NotARecording);
    EXPECT_EQ(plan.refusal_text, fifo +
                                     " is a FIFO (named pipe), not a file; ydscope reads a recording more than "
                                     "once, so save it to a file first");
  }
  EXPECT_FALSE(is_recording_file(fifo));
  const RecordingPlan zero = plan_recording("/dev/zero", RecordingUse::Replay, std::nullopt, std::nullopt);
  EXPECT_EQ(zero.refusal_text.rfind("/dev/zero is a device, not a file; ", 0), 0u) << zero.refusal_text;
}

// Issue 26: a file corrupt before its model record said "does not say which lidar made it; pass
// --model", while the corruption was the cause. Every use names it, where it is, and what helps.
TEST_F(RecordingPlanTest, DamageBeforeTheModelRecordIsTheReasonGiven) {
  const auto corrupt_after = [&](const std::string& name, const RawRecording& head) {
    std::vector<std::uint8_t> bytes = head.bytes();
    RecordHeader bad;
    bad.type = static_cast<std::uint8_t>(RecordType::DeviceToHost);
    bad.length = 0xFFFFFFFF;
    const auto header = encode_record_header(bad);
    bytes.insert(bytes.end(), header.begin(), header.end());
    RawRecording model_later(1, 16, "model=G6\n");  // the record the damage hides
    bytes.insert(bytes.end(), model_later.bytes().begin() + kFileHeaderSize, model_later.bytes().end());
    const std::string path = (dir_ / name).string();
    test::write_file_bytes(path, bytes);
    return std::pair{path, head.bytes().size()};
  };
  RawRecording commands_only(1, 16, "port=/dev/pts/1\n");
  commands_only.add(RecordType::HostToDevice, 1000, {0xA5, 0x90});
  const auto [no_bytes, at] = corrupt_after("commands.ydrec", commands_only);
  const std::string damage = no_bytes + " is corrupt at byte " + std::to_string(at) +
                             " (record type 1, length 4294967295); the 2 records "
                             "before it are intact, and none of them ";
  RecordingPlan plan = plan_recording(no_bytes, RecordingUse::Decode, std::nullopt, std::nullopt);
  EXPECT_EQ(plan.refusal, RecordingRefusal::Damaged);
  EXPECT_EQ(plan.refusal_text, damage + "says which lidar made it: nothing to decode");
  plan = plan_recording(no_bytes, RecordingUse::Replay, std::nullopt, std::nullopt);
  EXPECT_EQ(plan.refusal, RecordingRefusal::NothingToPlay);
  EXPECT_EQ(plan.refusal_text, damage + "holds bytes from a device: nothing to replay");
  EXPECT_EQ(plan_recording(no_bytes, RecordingUse::Replay, "G6", std::nullopt).refusal_text, plan.refusal_text);
  // A chosen model decodes the intact part, and the damage is its warning.
  plan = plan_recording(no_bytes, RecordingUse::Decode, "G6", std::nullopt);
  ASSERT_TRUE(plan.usable()) << plan.refusal_text;
  EXPECT_EQ(plan.warnings(), std::vector<std::string>{damage.substr(0, damage.find(", and none"))});

  RawRecording with_bytes(1, 16, "port=/dev/pts/1\n");
  with_bytes.add_device_records({0, 1000, 2000});
  const std::string some_bytes = corrupt_after("bytes.ydrec", with_bytes).first;
  plan = plan_recording(some_bytes, RecordingUse::Replay, std::nullopt, std::nullopt);
  EXPECT_EQ(plan.refusal, RecordingRefusal::NeedsModel);
  EXPECT_NE(plan.refusal_text.find(" is corrupt at byte "), std::string::npos) << plan.refusal_text;
  EXPECT_NE(plan.refusal_text.find(", and none of them says which lidar made it: pass --model (" + kModels +
                                   ") to decode the 3 bytes from the device before it"),
            std::string::npos)
      << plan.refusal_text;
  // Cut off before the model record: the cut is the cause, in the same way.
  std::vector<std::uint8_t> cut = with_bytes.bytes();
  cut.insert(cut.end(), {3, 0, 0});
  test::write_file_bytes((dir_ / "cut.ydrec").string(), cut);
  plan = plan_recording((dir_ / "cut.ydrec").string(), RecordingUse::Decode, std::nullopt, std::nullopt);
  EXPECT_EQ(plan.refusal_text.rfind((dir_ / "cut.ydrec").string() + " ends inside a record header at byte ", 0), 0u)
      << plan.refusal_text;
}

}  // namespace
}  // namespace ydscope
