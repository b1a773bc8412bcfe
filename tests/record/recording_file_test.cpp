// The .ydrec format: write/read round trip, metadata, truncation at every byte of the last
// record, corruption, magic detection, flushing so a killed recorder leaves a readable file.
#include <signal.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstdio>
#include <filesystem>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "core/record/recording_reader.h"
#include "core/record/recording_writer.h"
#include "support/raw_recording.h"
#include "test_data.h"
#include "support/temp_dir.h"

namespace ydscope {
namespace {

namespace fs = std::filesystem;
using Bytes = std::vector<std::uint8_t>;

struct Expected {
  RecordType type;
  std::int64_t t_ns;
  Bytes payload;
};

class RecordingFileTest : public ::testing::Test {
 protected:
  std::string path(const std::string& name) const { return dir_.file(name); }

  static Bytes file_bytes(const std::string& file) { return test::read_file_bytes(file); }
  static void write_bytes(const std::string& file, const Bytes& bytes) { test::write_file_bytes(file, bytes); }
  // Every record of a file, as the reader returns them.
  static std::vector<Expected> read_all(RecordingReader& reader) {
    std::vector<Expected> out;
    RecordView record;
    while (reader.next(record))
      out.push_back({record.type, record.t_ns, Bytes(record.payload.begin(), record.payload.end())});
    return out;
  }

  test::TempDir dir_{"recording-file"};
};

constexpr std::int64_t kStart = 5'000'000'000;  // an arbitrary steady-clock origin

RecordingMetadata sample_metadata() {
  RecordingMetadata metadata;
  metadata.model = "G6";
  metadata.baud = 512000;
  metadata.distance_scale = 0.25;
  metadata.port = "/dev/ttyUSB0";
  metadata.start_wall_time = "2026-11-22T02:20:00.123Z";
  return metadata;
}

TEST_F(RecordingFileTest, RoundTripKeepsEveryRecordInOrder) {
  std::string error;
  auto writer = RecordingWriter::create(path("a.ydrec"), sample_metadata(), kStart, error);
  ASSERT_TRUE(writer) << error;
  const Bytes stop{0xA5, 0x65};
  const Bytes reply{0xA5, 0x5A, 0x05, 0x00, 0x00, 0x40, 0x81};
  const Bytes packet{0xAA, 0x55, 0x01, 0x01, 0x03, 0x00, 0x03, 0x00, 0x57, 0x55, 0x00, 0x00};
  ASSERT_TRUE(writer->append(Direction::HostToDevice, stop, kStart + 1000));
  ASSERT_TRUE(writer->append(Direction::DeviceToHost, reply, kStart + 2'000'000));
  RecordingMetadata device;
  device.model_code = 13;
  device.firmware = "3.1";
  device.hardware = 2;
  device.serial = "2020112400002345";
  ASSERT_TRUE(writer->update_metadata(device, kStart + 3'000'000));
  ASSERT_TRUE(writer->append(Direction::DeviceToHost, packet, kStart + 4'000'000));
  ASSERT_TRUE(writer->append(Direction::DeviceToHost, {}, kStart + 5'000'000));  // not recorded
  EXPECT_EQ(writer->bytes(Direction::DeviceToHost), reply.size() + packet.size());
  EXPECT_EQ(writer->bytes(Direction::HostToDevice), 2u);
  ASSERT_TRUE(writer->close()) << writer->error();
  EXPECT_EQ(writer->file_size(), fs::file_size(path("a.ydrec")));

  auto reader = RecordingReader::open(path("a.ydrec"), error);
  ASSERT_TRUE(reader) << error;
  EXPECT_EQ(reader->version(), kRecordingVersion);
  EXPECT_EQ(reader->metadata().model, "G6");  // known before iterating
  const auto records = read_all(*reader);
  ASSERT_EQ(records.size(), 5u);
  EXPECT_EQ(records[0].type, RecordType::Metadata);
  EXPECT_EQ(records[0].t_ns, 0);
  EXPECT_EQ(records[1].type, RecordType::HostToDevice);
  EXPECT_EQ(records[1].t_ns, 1000);
  EXPECT_EQ(records[1].payload, stop);
  EXPECT_EQ(records[2].type, RecordType::DeviceToHost);
  EXPECT_EQ(records[2].t_ns, 2'000'000);
  EXPECT_EQ(records[2].payload, reply);
  EXPECT_EQ(records[3].type, RecordType::Metadata);
  EXPECT_EQ(records[4].payload, packet);
  EXPECT_EQ(records[4].t_ns, 4'000'000);
  EXPECT_FALSE(reader->truncated());
  EXPECT_FALSE(reader->corrupt());

  RecordingMetadata expected = sample_metadata();
  expected.merge(device);
  EXPECT_EQ(reader->metadata(), expected);
  EXPECT_EQ(writer->metadata(), expected);

  reader->rewind();
  EXPECT_EQ(read_all(*reader).size(), 5u);

  const auto summary = summarize_recording(path("a.ydrec"), error);
  ASSERT_TRUE(summary) << error;
  EXPECT_EQ(summary->records, 5u);
  EXPECT_EQ(summary->device_bytes, reply.size() + packet.size());
  EXPECT_EQ(summary->host_bytes, 2u);
  EXPECT_EQ(summary->duration_ns, 4'000'000);
  EXPECT_EQ(summary->metadata, expected);
}

TEST_F(RecordingFileTest, TimesAreRelativeToStartAndNeverGoBack) {
  std::string error;
  auto writer = RecordingWriter::create(path("t.ydrec"), {}, kStart, error);
  ASSERT_TRUE(writer) << error;
  const Bytes one{1};
  ASSERT_TRUE(writer->append(Direction::DeviceToHost, one, kStart + 500));
  ASSERT_TRUE(writer->append(Direction::DeviceToHost, one, kStart + 100));  // clock went back
  ASSERT_TRUE(writer->append(Direction::DeviceToHost, one, kStart - 7));
  writer->close();
  auto reader = RecordingReader::open(path("t.ydrec"), error);
  ASSERT_TRUE(reader) << error;
  const auto records = read_all(*reader);
  ASSERT_EQ(records.size(), 4u);
  EXPECT_EQ(records[1].t_ns, 500);
  EXPECT_EQ(records[2].t_ns, 500);
  EXPECT_EQ(records[3].t_ns, 500);
  EXPECT_TRUE(reader->metadata().start_wall_time.has_value());  // filled in by the writer
}

TEST_F(RecordingFileTest, CutInsideTheLastRecordKeepsEveryEarlierRecord) {
  std::string error;
  auto writer = RecordingWriter::create(path("full.ydrec"), sample_metadata(), kStart, error);
  ASSERT_TRUE(writer) << error;
  for (int i = 0; i < 4; ++i) {
    const Bytes chunk(static_cast<std::size_t>(10 + i), static_cast<std::uint8_t>(0x40 + i));
    ASSERT_TRUE(writer->append(Direction::DeviceToHost, chunk, kStart + i * 1000));
  }
  const std::uint64_t before_last = writer->file_size();
  const Bytes last{0xA5, 0x65, 0xA5, 0x60};
  ASSERT_TRUE(writer->append(Direction::HostToDevice, last, kStart + 9000));
  ASSERT_TRUE(writer->close());
  const Bytes whole = file_bytes(path("full.ydrec"));
  ASSERT_EQ(whole.size(), before_last + kRecordHeaderSize + last.size());

  auto full_reader = RecordingReader::open(path("full.ydrec"), error);
  ASSERT_TRUE(full_reader) << error;
  const auto all = read_all(*full_reader);
  ASSERT_EQ(all.size(), 6u);
  const std::vector<Expected> earlier(all.begin(), all.end() - 1);

  for (std::size_t cut = before_last; cut < whole.size(); ++cut) {
    SCOPED_TRACE("cut at byte " + std::to_string(cut));
    write_bytes(path("cut.ydrec"), Bytes(whole.begin(), whole.begin() + static_cast<std::ptrdiff_t>(cut)));
    auto reader = RecordingReader::open(path("cut.ydrec"), error);
    ASSERT_TRUE(reader) << error;
    const auto records = read_all(*reader);
    ASSERT_EQ(records.size(), earlier.size());
    for (std::size_t i = 0; i < records.size(); ++i) {
      EXPECT_EQ(records[i].type, earlier[i].type);
      EXPECT_EQ(records[i].t_ns, earlier[i].t_ns);
      EXPECT_EQ(records[i].payload, earlier[i].payload);
    }
    EXPECT_EQ(reader->truncated(), cut != before_last);  // a cut on a boundary is a clean end
    EXPECT_FALSE(reader->corrupt());
    if (reader->truncated()) {
      EXPECT_NE(reader->warning().find("at byte " + std::to_string(before_last)), std::string::npos)
          << reader->warning();
      EXPECT_NE(reader->warning().find("the 5 records before it are intact"), std::string::npos) << reader->warning();
    }
  }
}

TEST_F(RecordingFileTest, MagicIdentifiesRecordings) {
  std::string error;
  auto writer = RecordingWriter::create(path("m.ydrec"), {}, kStart, error);
  ASSERT_TRUE(writer) << error;
  writer->close();
  const Bytes head = file_bytes(path("m.ydrec"));
  EXPECT_TRUE(is_recording(head));
  EXPECT_FALSE(is_recording(std::span<const std::uint8_t>(head).first(11)));  // too short to tell
  EXPECT_TRUE(is_recording_file(path("m.ydrec")));

  const std::string raw = (test::captures_dir() / "x4-scan1.bin").string();
  EXPECT_FALSE(is_recording_file(raw));
  EXPECT_FALSE(is_recording_file(path("missing.ydrec")));
  EXPECT_FALSE(RecordingReader::open(raw, error));
  EXPECT_EQ(error, raw + " is not a ydscope recording (no YDSCOPE-REC header)");
  EXPECT_FALSE(RecordingReader::open(path("missing.ydrec"), error));
  EXPECT_NE(error.find("cannot open recording"), std::string::npos);
}

TEST_F(RecordingFileTest, NewerVersionIsRefusedWithAHint) {
  std::string error;
  auto writer = RecordingWriter::create(path("v.ydrec"), {}, kStart, error);
  ASSERT_TRUE(writer) << error;
  writer->close();
  Bytes bytes = file_bytes(path("v.ydrec"));
  bytes[12] = kMultiSourceVersion + 1;  // version 2 (several sources) reads; 3 is from the future
  write_bytes(path("v.ydrec"), bytes);
  EXPECT_FALSE(RecordingReader::open(path("v.ydrec"), error));
  EXPECT_NE(error.find("version 3 recording"), std::string::npos) << error;
}

TEST_F(RecordingFileTest, UnknownRecordTypesAreSkippedAndBadLengthsAreCorrupt) {
  std::string error;
  auto writer = RecordingWriter::create(path("u.ydrec"), {}, kStart, error);
  ASSERT_TRUE(writer) << error;
  const Bytes data{1, 2, 3};
  ASSERT_TRUE(writer->append(Direction::DeviceToHost, data, kStart + 10));
  writer->close();
  Bytes bytes = file_bytes(path("u.ydrec"));
  // A record of a future type 9, then our data again.
  RecordHeader future;
  future.type = 9;
  future.length = 2;
  future.t_ns = 20;
  const auto head = encode_record_header(future);
  bytes.insert(bytes.end(), head.begin(), head.end());
  bytes.insert(bytes.end(), {0xEE, 0xEE});
  RecordHeader again{1, 0, 3, 30};
  const auto head2 = encode_record_header(again);
  bytes.insert(bytes.end(), head2.begin(), head2.end());
  bytes.insert(bytes.end(), data.begin(), data.end());
  write_bytes(path("u.ydrec"), bytes);

  auto reader = RecordingReader::open(path("u.ydrec"), error);
  ASSERT_TRUE(reader) << error;
  auto records = read_all(*reader);
  ASSERT_EQ(records.size(), 3u);
  EXPECT_EQ(records[2].t_ns, 30);
  EXPECT_EQ(records[2].payload, data);
  EXPECT_FALSE(reader->corrupt());

  // A length beyond the format's bound: corrupt from there on, earlier records kept.
  RecordHeader huge{1, 0, kMaxRecordPayload + 1, 40};
  const auto head3 = encode_record_header(huge);
  bytes.insert(bytes.end(), head3.begin(), head3.end());
  write_bytes(path("u.ydrec"), bytes);
  reader = RecordingReader::open(path("u.ydrec"), error);
  ASSERT_TRUE(reader) << error;
  records = read_all(*reader);
  EXPECT_EQ(records.size(), 3u);
  EXPECT_TRUE(reader->corrupt());
  EXPECT_NE(reader->error().find("is corrupt at byte"), std::string::npos) << reader->error();
}

TEST_F(RecordingFileTest, OversizedReadIsSplitWithoutLosingBytes) {
  std::string error;
  auto writer = RecordingWriter::create(path("big.ydrec"), {}, kStart, error);
  ASSERT_TRUE(writer) << error;
  Bytes big(kMaxRecordPayload * 2 + 5);
  for (std::size_t i = 0; i < big.size(); ++i) big[i] = static_cast<std::uint8_t>(i * 7);
  ASSERT_TRUE(writer->append(Direction::DeviceToHost, big, kStart + 1));
  writer->close();
  auto reader = RecordingReader::open(path("big.ydrec"), error);
  ASSERT_TRUE(reader) << error;
  Bytes joined;
  for (const auto& record : read_all(*reader))
    if (record.type == RecordType::DeviceToHost)
      joined.insert(joined.end(), record.payload.begin(), record.payload.end());
  EXPECT_EQ(joined, big);
}

TEST_F(RecordingFileTest, KilledRecorderLeavesEverythingUpToTheLastFlushReadable) {
  const std::string file = path("killed.ydrec");
  const pid_t child = ::fork();
  ASSERT_GE(child, 0);
  if (child == 0) {
    std::string error;
    auto writer = RecordingWriter::create(file, sample_metadata(), kStart, error);
    if (!writer) ::_exit(3);
    // 30 records over 290 ms of recorded time: the writer must have flushed by the last one.
    for (int i = 0; i < 30; ++i) {
      const Bytes chunk(100, static_cast<std::uint8_t>(i));
      writer->append(Direction::DeviceToHost, chunk, kStart + i * 10'000'000LL);
    }
    ::raise(SIGKILL);  // no destructor, no close: like a crash
    ::_exit(4);
  }
  int status = 0;
  ASSERT_EQ(::waitpid(child, &status, 0), child);
  ASSERT_TRUE(WIFSIGNALED(status)) << "child exited with " << WEXITSTATUS(status);

  std::string error;
  auto reader = RecordingReader::open(file, error);
  ASSERT_TRUE(reader) << error;
  EXPECT_EQ(reader->metadata().model, "G6");
  std::size_t data_records = 0;
  RecordView record;
  while (reader->next(record)) {
    if (record.type != RecordType::DeviceToHost) continue;
    EXPECT_EQ(record.payload.size(), 100u);
    EXPECT_EQ(record.payload[0], static_cast<std::uint8_t>(data_records));
    ++data_records;
  }
  EXPECT_FALSE(reader->corrupt());
  // Flushed at t >= 100 ms and >= 200 ms: at least the records up to 200 ms (index 20) are there.
  EXPECT_GE(data_records, 21u);
}

TEST_F(RecordingFileTest, FullDiskIsOneSentence) {
  std::string error;
  // /dev/full accepts open() and fails every write with ENOSPC; the metadata record is flushed.
  EXPECT_FALSE(RecordingWriter::create("/dev/full", sample_metadata(), kStart, error));
  EXPECT_NE(error.find("No space left on device; free some disk space"), std::string::npos) << error;
  EXPECT_FALSE(RecordingWriter::create(path("no-such-dir/x.ydrec"), {}, kStart, error));
  EXPECT_NE(error.find("check that the folder exists"), std::string::npos) << error;
}

}  // namespace
}  // namespace ydscope
