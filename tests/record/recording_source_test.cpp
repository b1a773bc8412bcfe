// A recording's source entry as a SourceInfo and back (core/record/recording_source): what a
// file's metadata says a source is, and what a recording of a set writes for each source. A set of
// one writes what a lone lidar's version-1 file always held (no name, no pose); several are named
// and placed.
#include <vector>

#include <gtest/gtest.h>

#include "core/record/recording_source.h"

namespace ydscope {
namespace {

SourceInfo lidar(const char* name, Pose pose, std::optional<Model> model, const char* serial) {
  SourceInfo info;
  info.name = name;
  info.pose = pose;
  info.model = model;
  info.serial = serial;
  return info;
}

TEST(RecordingSource, AnEntryWithEverythingReadsAsItsSourceInfo) {
  RecordingMetadata metadata;
  metadata.name = "front";
  metadata.pose = Pose{0.25, -0.5, 90, true, 3};
  metadata.model = "tg30";  // the name is looked up whatever its case
  metadata.serial = "2021092400010008";
  metadata.port = "/dev/ttyUSB0";  // not what the lidar is: left out

  const SourceInfo info = source_info_of(metadata, 3);
  EXPECT_EQ(info.name, "front");
  EXPECT_EQ(info.pose, (Pose{0.25, -0.5, 90, true, 3}));
  EXPECT_EQ(info.model, Model::TG30);
  EXPECT_EQ(info.serial, "2021092400010008");
  EXPECT_EQ(info.frame_id, "");
}

TEST(RecordingSource, AnEntryWithNothingIsSourceIdAtTheIdentityWithNoModel) {
  RecordingMetadata metadata;
  metadata.model = "X99";  // a model this ydscope does not know: decode as the device says

  const SourceInfo info = source_info_of(metadata, 2);
  EXPECT_EQ(info.name, "source2");
  EXPECT_EQ(info.pose, Pose{});
  EXPECT_FALSE(info.model.has_value());
  EXPECT_EQ(info.serial, "");
}

TEST(RecordingSource, ASetOfOneWritesNeitherNameNorPose) {
  const std::vector<SourceInfo> one = {lidar("lidar0", Pose{1, 2, 30, false, 0}, Model::G6, "")};

  const RecordingMetadata entry = source_entry_of(one, 0);
  EXPECT_FALSE(entry.name.has_value());
  EXPECT_FALSE(entry.pose.has_value());
  EXPECT_EQ(entry.model, "G6");
  EXPECT_FALSE(entry.serial.has_value());
  // Nothing else is written: what the session learns later merges into it.
  RecordingMetadata expected;
  expected.model = "G6";
  EXPECT_EQ(entry, expected);
}

TEST(RecordingSource, SeveralSourcesAreEachNamedAndPlaced) {
  const std::vector<SourceInfo> two = {lidar("left", Pose{0.1, 0.2, 90, false, 0}, Model::G1, "111"),
                                       lidar("right", Pose{-0.1, 0.2, -90, true, 0}, std::nullopt, "")};

  const RecordingMetadata left = source_entry_of(two, 0);
  EXPECT_EQ(left.name, "left");
  EXPECT_EQ(left.pose, (Pose{0.1, 0.2, 90, false, 0}));
  EXPECT_EQ(left.model, "G1");
  EXPECT_EQ(left.serial, "111");

  const RecordingMetadata right = source_entry_of(two, 1);
  EXPECT_EQ(right.name, "right");
  EXPECT_EQ(right.pose, (Pose{-0.1, 0.2, -90, true, 0}));
  EXPECT_FALSE(right.model.has_value());
  EXPECT_FALSE(right.serial.has_value());
}

TEST(RecordingSource, EachSourceOfSeveralComesBackAsItWasWritten) {
  const std::vector<SourceInfo> three = {lidar("a", Pose{0, 0, 0, false, 0}, Model::G6, "1"),
                                         lidar("b", Pose{1.5, -2, 45, false, 0}, Model::TG15, ""),
                                         lidar("c", Pose{0, 3, 180, true, 10}, std::nullopt, "3")};
  for (std::size_t id = 0; id < three.size(); ++id)
    EXPECT_EQ(source_info_of(source_entry_of(three, id), id), three[id]) << "source " << id;
}

}  // namespace
}  // namespace ydscope
