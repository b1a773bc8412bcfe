// Recording format version 2: several sources in one file, each with its id in every record and
// its own metadata (name, pose); one source still writes version 1, byte for byte as before.
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "core/record/recording_reader.h"
#include "core/record/recording_writer.h"
#include "support/raw_recording.h"
#include "support/temp_dir.h"

namespace ydscope {
namespace {

using Bytes = std::vector<std::uint8_t>;

constexpr std::int64_t kSourcesStart = 7'000'000'000;

class RecordingSourcesTest : public ::testing::Test {
 protected:
  std::string path(const std::string& name) const { return dir_.file(name); }

  test::TempDir dir_{"sources"};
};

RecordingMetadata source(const char* name, const char* model, const char* port, Pose pose) {
  RecordingMetadata metadata;
  metadata.name = name;
  metadata.model = model;
  metadata.port = port;
  metadata.pose = pose;
  return metadata;
}

TEST_F(RecordingSourcesTest, ThreeSourcesRoundTripWithTheirIdsAndMetadata) {
  std::string error;
  auto writer = RecordingWriter::create_sources(
      path("three.ydrec"),
      {source("left", "G1", "/dev/pts/1", {0.1, 0.2, 90, false}), source("mid", "G6", "/dev/pts/2", {0, 0, 0, false}),
       source("right", "TG30", "tcp://h:1", {-0.1, 0.2, -90, true})},
      kSourcesStart, error);
  ASSERT_TRUE(writer) << error;
  ASSERT_TRUE(writer->append(Direction::DeviceToHost, Bytes{1, 1}, kSourcesStart + 10, 0));
  ASSERT_TRUE(writer->append(Direction::HostToDevice, Bytes{0xA5, 0x60}, kSourcesStart + 20, 2));
  ASSERT_TRUE(writer->append(Direction::DeviceToHost, Bytes{2, 2, 2}, kSourcesStart + 30, 1));
  RecordingMetadata device;
  device.serial = "123";
  ASSERT_TRUE(writer->update_metadata(device, kSourcesStart + 40, 2));
  ASSERT_TRUE(writer->append(Direction::DeviceToHost, Bytes{3}, kSourcesStart + 50, 2));
  // A source the file was not made with is refused, in words.
  EXPECT_FALSE(writer->append(Direction::DeviceToHost, Bytes{9}, kSourcesStart + 60, 3));
  EXPECT_NE(writer->error().find("records 3 sources"), std::string::npos) << writer->error();
  writer->close();

  auto reader = RecordingReader::open(path("three.ydrec"), error);
  ASSERT_TRUE(reader) << error;
  EXPECT_EQ(reader->version(), kMultiSourceVersion);
  // Every source is known before the first link byte.
  ASSERT_EQ(reader->source_count(), 3u);
  EXPECT_EQ(reader->source_metadata(0).name, "left");
  EXPECT_EQ(reader->source_metadata(1).model, "G6");
  EXPECT_EQ(reader->source_metadata(2).pose, (Pose{-0.1, 0.2, -90, true}));
  EXPECT_EQ(reader->source_metadata(0).start_wall_time, reader->source_metadata(2).start_wall_time);
  EXPECT_EQ(reader->metadata().name, "left");  // metadata() is source 0's

  struct Seen {
    RecordType type;
    std::uint16_t source;
    Bytes payload;
  };
  std::vector<Seen> seen;
  RecordView record;
  while (reader->next(record))
    seen.push_back({record.type, record.source, Bytes(record.payload.begin(), record.payload.end())});
  ASSERT_EQ(seen.size(), 8u);
  for (std::uint16_t id = 0; id < 3; ++id) {
    EXPECT_EQ(seen[id].type, RecordType::Metadata);
    EXPECT_EQ(seen[id].source, id);
  }
  EXPECT_EQ(seen[3].source, 0);
  EXPECT_EQ(seen[3].payload, (Bytes{1, 1}));
  EXPECT_EQ(seen[4].source, 2);
  EXPECT_EQ(seen[4].type, RecordType::HostToDevice);
  EXPECT_EQ(seen[5].source, 1);
  EXPECT_EQ(seen[6].type, RecordType::Metadata);
  EXPECT_EQ(seen[7].source, 2);
  EXPECT_EQ(reader->source_metadata(2).serial, "123");
  EXPECT_EQ(reader->source_metadata(2).name, "right");  // a later record adds, never replaces all
  EXPECT_TRUE(reader->damage().empty());

  const auto summary = summarize_recording(path("three.ydrec"), error);
  ASSERT_TRUE(summary) << error;
  EXPECT_EQ(summary->version, kMultiSourceVersion);
  ASSERT_EQ(summary->sources.size(), 3u);
  EXPECT_EQ(summary->sources[0].device_bytes, 2u);
  EXPECT_EQ(summary->sources[1].device_bytes, 3u);
  EXPECT_EQ(summary->sources[2].device_bytes, 1u);
  EXPECT_EQ(summary->sources[2].host_bytes, 2u);
  EXPECT_EQ(summary->sources[1].metadata.port, "/dev/pts/2");
  EXPECT_EQ(summary->device_bytes, 6u);
}

TEST_F(RecordingSourcesTest, OneSourceStillWritesVersionOneByteForByte) {
  RecordingMetadata metadata;
  metadata.model = "G6";
  metadata.start_wall_time = "2026-12-02T08:00:00.000Z";
  std::string error;
  auto one = RecordingWriter::create(path("one.ydrec"), metadata, kSourcesStart, error);
  ASSERT_TRUE(one) << error;
  auto listed = RecordingWriter::create_sources(path("listed.ydrec"), std::vector{metadata}, kSourcesStart, error);
  ASSERT_TRUE(listed) << error;
  for (RecordingWriter* writer : {one.get(), listed.get()}) {
    ASSERT_TRUE(writer->append(Direction::DeviceToHost, Bytes{0xAA, 0x55}, kSourcesStart + 5));
    writer->close();
  }
  const Bytes bytes = test::read_file_bytes(path("one.ydrec"));
  EXPECT_EQ(bytes, test::read_file_bytes(path("listed.ydrec")));
  ASSERT_GE(bytes.size(), 20u);
  EXPECT_EQ(bytes[12], 1);  // version 1
  EXPECT_EQ(bytes[13], 0);
  EXPECT_EQ(bytes[16 + 2], 0);  // the reserved field stays 0
  EXPECT_EQ(bytes[16 + 3], 0);
}

TEST_F(RecordingSourcesTest, VersionOneIgnoresItsReservedFieldAsItAlwaysDid) {
  test::RawRecording raw(1);
  raw.add(RecordType::DeviceToHost, 100, Bytes{7}, /*source=*/513);
  raw.write(path("v1.ydrec"));
  std::string error;
  auto reader = RecordingReader::open(path("v1.ydrec"), error);
  ASSERT_TRUE(reader) << error;
  RecordView record;
  ASSERT_TRUE(reader->next(record));
  ASSERT_TRUE(reader->next(record));
  EXPECT_EQ(record.source, 0);
  EXPECT_EQ(reader->source_count(), 1u);
  EXPECT_FALSE(reader->corrupt());
}

TEST_F(RecordingSourcesTest, ASourceIdBeyondTheLimitIsCorruptionInOneSentence) {
  test::RawRecording raw(2);
  raw.add(RecordType::DeviceToHost, 100, Bytes{7}, 1);
  raw.add(RecordType::DeviceToHost, 200, Bytes{8}, kMaxRecordingSources);
  raw.write(path("bad.ydrec"));
  std::string error;
  auto reader = RecordingReader::open(path("bad.ydrec"), error);
  ASSERT_TRUE(reader) << error;
  RecordView record;
  int records = 0;
  while (reader->next(record)) ++records;
  EXPECT_EQ(records, 2);
  ASSERT_TRUE(reader->corrupt());
  EXPECT_EQ(reader->error(), path("bad.ydrec") +
                                 " is corrupt at byte 58 (source 64; at most 64 sources); the 2 records "
                                 "before it are intact");
}

TEST_F(RecordingSourcesTest, ADamagedPoseIsAWarningAndTheRestOfTheMetadataStays) {
  test::RawRecording raw(2, 16, "model=G1\nname=front\npose=0,0,ninety\n");
  raw.add(RecordType::Metadata, 0, Bytes{'n', 'a', 'm', 'e', '=', 'b', '\n'}, 1);
  raw.write(path("pose.ydrec"));
  std::string error;
  auto reader = RecordingReader::open(path("pose.ydrec"), error);
  ASSERT_TRUE(reader) << error;
  ASSERT_EQ(reader->source_count(), 2u);
  EXPECT_EQ(reader->source_metadata(0).name, "front");
  EXPECT_FALSE(reader->source_metadata(0).pose);
  EXPECT_EQ(reader->source_metadata(1).name, "b");
  ASSERT_EQ(reader->metadata_warnings().size(), 1u);
  EXPECT_NE(reader->metadata_warnings()[0].find("'0,0,ninety'"), std::string::npos) << reader->metadata_warnings()[0];
}

// A recording from before REP-103 (a pose, no pose_convention) keeps its lidars where they were:
// converted once on reading, said once; one written now carries the marker and reads back as is.
TEST_F(RecordingSourcesTest, APoseFromBeforeRep103IsConvertedWithOneWarning) {
  test::RawRecording raw(2, 16, "model=G1\nname=front\npose=-1,0.5,0\n");
  raw.add(RecordType::Metadata, 0, Bytes{'n', 'a', 'm', 'e', '=', 'b', '\n'}, 1);
  raw.write(path("old-pose.ydrec"));
  std::string error;
  auto reader = RecordingReader::open(path("old-pose.ydrec"), error);
  ASSERT_TRUE(reader) << error;
  EXPECT_EQ(reader->source_metadata(0).pose, (Pose{0.5, 1, 180, false}));
  ASSERT_EQ(reader->metadata_warnings().size(), 1u);
  EXPECT_NE(reader->metadata_warnings()[0].find("REP-103"), std::string::npos) << reader->metadata_warnings()[0];

  RecordingMetadata now;
  now.pose = Pose{0.5, 1, 180, false};
  const std::string text = now.encode();
  EXPECT_NE(text.find("pose_convention=rep103\n"), std::string::npos) << text;
  std::vector<std::string> warnings;
  EXPECT_EQ(RecordingMetadata::parse(text, &warnings).pose, now.pose);
  EXPECT_TRUE(warnings.empty());
  EXPECT_TRUE(RecordingMetadata::parse(text).extra.empty());  // the marker is no unknown key
}

}  // namespace
}  // namespace ydscope
