// SourceSet (core/session/source_set): the lidars one command drives together. It connects them
// all, says when their start has settled (every one scanning, or in trouble before it ever
// scanned, with that one's sentence), records them all into one .ydrec, and one lidar is a set of
// one: its recording is version 1 without name or pose, as a lone lidar's always was.
#include <stdexcept>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "core/record/recording_reader.h"
#include "core/session/source_set.h"
#include "support/session_test_support.h"

namespace ydscope {
namespace {

using namespace test;

SourceSpec spec(const char* name, const std::string& port, Model model, Pose pose = {}) {
  SourceSpec s;
  s.info.name = name;
  s.info.pose = pose;
  s.info.model = model;
  s.config = config_for(port, model);
  return s;
}

// Looks at the set's start (as a command does at its start) until it settles; bounded.
SetStart wait_until_settled(SourceSet& set) {
  const auto deadline = std::chrono::steady_clock::now() + kPatience;
  SetStart start = set.start_state();
  while (!start.settled && std::chrono::steady_clock::now() < deadline) {
    std::this_thread::sleep_for(10ms);
    start = set.start_state();
  }
  return start;
}

TEST(SourceSet, AnEmptySetIsRefused) { EXPECT_THROW(SourceSet(std::vector<SourceSpec>{}), std::invalid_argument); }

TEST(SourceSet, ConnectAllStartsEveryLidarAndSettlesWhenEachScans) {
  SimOnPty g6(Model::G6);
  SimOnPty g1(Model::G1);
  SourceSet set({spec("left", g6.port(), Model::G6, Pose{0.1, 0, 90, false, 0}), spec("right", g1.port(), Model::G1)});
  ASSERT_EQ(set.size(), 2u);
  EXPECT_EQ(set.info(0).name, "left");
  EXPECT_EQ(set.info(0).pose, (Pose{0.1, 0, 90, false, 0}));
  EXPECT_EQ(set.config(1).address, g1.port());

  // Before anything connects, nothing has scanned and nothing is in trouble: not settled.
  const SetStart before = set.start_state();
  EXPECT_FALSE(before.settled);
  EXPECT_FALSE(before.any_scanned);
  EXPECT_EQ(before.failure, "");

  set.connect_all();
  const SetStart start = wait_until_settled(set);
  ASSERT_TRUE(start.settled);
  EXPECT_TRUE(start.any_scanned);
  EXPECT_EQ(start.failure, "");
  EXPECT_TRUE(set.ever_scanned(0));
  EXPECT_TRUE(set.ever_scanned(1));
  // Each session is its own lidar: each reads its own model and delivers laps.
  const SessionSnapshot left = set.session(0).snapshot(), right = set.session(1).snapshot();
  ASSERT_TRUE(left.device && left.device->profile && right.device && right.device->profile);
  EXPECT_EQ(left.device->profile->model, Model::G6);
  EXPECT_EQ(right.device->profile->model, Model::G1);
  EXPECT_EQ(take_laps(set.session(0), 2), 2u);
  EXPECT_EQ(take_laps(set.session(1), 2), 2u);

  set.disconnect_all();
  for (std::size_t id = 0; id < set.size(); ++id) EXPECT_EQ(set.session(id).snapshot().state, LinkState::Idle);
}

TEST(SourceSet, ALidarInTroubleBeforeItEverScannedSettlesTheStartWithItsSentence) {
  SimOnPty g6(Model::G6);
  SourceSpec missing = spec("gone", "/dev/ydscope-no-such-port", Model::G1);
  missing.config.reconnect = false;
  SourceSet set({spec("here", g6.port(), Model::G6), missing});
  set.connect_all();
  // Settled once the one scans and the other has failed, whichever comes first.
  const auto deadline = std::chrono::steady_clock::now() + kPatience;
  SetStart start = set.start_state();
  while (!(start.settled && start.any_scanned) && std::chrono::steady_clock::now() < deadline) {
    std::this_thread::sleep_for(10ms);
    start = set.start_state();
  }
  ASSERT_TRUE(start.settled);
  EXPECT_TRUE(start.any_scanned);
  EXPECT_TRUE(set.ever_scanned(0));
  EXPECT_FALSE(set.ever_scanned(1));
  const SessionSnapshot gone = set.session(1).snapshot();
  EXPECT_EQ(gone.state, LinkState::Failed);
  // The failure is the session's own sentence, naming the port.
  EXPECT_EQ(start.failure, gone.message);
  EXPECT_NE(start.failure.find("/dev/ydscope-no-such-port"), std::string::npos) << start.failure;
}

TEST(SourceSet, EveryLidarInTroubleSettlesWithNoneScanned) {
  SourceSpec missing = spec("gone", "/dev/ydscope-no-such-port", Model::G6);
  missing.config.reconnect = false;
  SourceSet set({missing});
  set.connect_all();
  const SetStart start = wait_until_settled(set);
  ASSERT_TRUE(start.settled);
  EXPECT_FALSE(start.any_scanned);
  EXPECT_NE(start.failure.find("/dev/ydscope-no-such-port"), std::string::npos) << start.failure;
}

TEST(SourceSet, ASetOfOneRecordsAVersionOneFileWithoutNameOrPose) {
  SimOnPty g6(Model::G6);
  TempDir dir{"source_set"};
  SourceSet set({spec("lidar0", g6.port(), Model::G6, Pose{1, 2, 30, false, 0})});
  std::string error;
  auto recording = set.record(dir.file("one.ydrec"), error);
  ASSERT_TRUE(recording) << error;
  set.connect_all();
  ASSERT_TRUE(wait_until_settled(set).any_scanned);
  ASSERT_EQ(take_laps(set.session(0), 2), 2u);
  for (auto& closed : close_taps_together(recording_taps(set.sessions(), *recording))) EXPECT_TRUE(closed.get().ok);
  set.disconnect_all();
  recording.reset();

  auto reader = RecordingReader::open(dir.file("one.ydrec"), error);
  ASSERT_TRUE(reader) << error;
  EXPECT_EQ(reader->version(), kRecordingVersion);
  EXPECT_EQ(reader->source_count(), 1u);
  EXPECT_FALSE(reader->metadata().name.has_value());
  EXPECT_FALSE(reader->metadata().pose.has_value());
  EXPECT_EQ(reader->metadata().model, "G6");
  EXPECT_EQ(reader->metadata().port, g6.port());
}

TEST(SourceSet, SeveralLidarsRecordOneVersionTwoFileNamingAndPlacingEach) {
  SimOnPty g6(Model::G6);
  SimOnPty g1(Model::G1);
  TempDir dir{"source_set"};
  SourceSet set({spec("left", g6.port(), Model::G6, Pose{0.1, 0.2, 90, false, 0}),
                 spec("right", g1.port(), Model::G1, Pose{-0.1, 0.2, -90, true, 0})});
  std::string error;
  auto recording = set.record(dir.file("two.ydrec"), error);
  ASSERT_TRUE(recording) << error;
  set.connect_all();
  const SetStart start = wait_until_settled(set);
  ASSERT_TRUE(start.settled && start.failure.empty()) << start.failure;
  for (auto& closed : close_taps_together(recording_taps(set.sessions(), *recording))) EXPECT_TRUE(closed.get().ok);
  set.disconnect_all();
  recording.reset();

  auto reader = RecordingReader::open(dir.file("two.ydrec"), error);
  ASSERT_TRUE(reader) << error;
  EXPECT_EQ(reader->version(), kMultiSourceVersion);
  ASSERT_EQ(reader->source_count(), 2u);
  EXPECT_EQ(reader->source_metadata(0).name, "left");
  EXPECT_EQ(reader->source_metadata(0).pose, (Pose{0.1, 0.2, 90, false, 0}));
  EXPECT_EQ(reader->source_metadata(0).port, g6.port());
  EXPECT_EQ(reader->source_metadata(1).name, "right");
  EXPECT_EQ(reader->source_metadata(1).pose, (Pose{-0.1, 0.2, -90, true, 0}));
  EXPECT_EQ(reader->source_metadata(1).model, "G1");
}

}  // namespace
}  // namespace ydscope
