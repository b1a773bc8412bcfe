// A device (or a recording) can claim anything in its fields; none of them may size an
// allocation or bound a loop. One test per field a device could lie about: a reply's length, a
// scan packet's LSN, the ranging codes, the firmware fields (model code, versions, serial), and a
// recording's record length and header size. Each feeds the lie and checks that the work done
// and the memory taken stay bounded by what really arrived (allocation_counter.h).
#include <gtest/gtest.h>

#include <filesystem>
#include <string>
#include <unistd.h>

#include "allocation_counter.h"
#include "core/protocol/model_profile.h"
#include "core/protocol/reply.h"
#include "core/protocol/reply_reader.h"
#include "core/record/recording_reader.h"
#include "support/raw_recording.h"
#include "protocol_test_support.h"
#include "support/temp_dir.h"

namespace ydscope {
namespace {

using test::Bytes;

TEST(LyingDevice, AReplyLengthOfAGigabyteAllocatesNothingAndEndsAtTheJunkLimit) {
  // A5 5A, length 0x3FFFFFFF (the widest the 30 bits allow), single mode, device-info type, then
  // 256 KiB that never make a reply.
  Bytes stream{0xA5, 0x5A, 0xFF, 0xFF, 0xFF, 0x3F, 0x04};
  stream.resize(stream.size() + 256 * 1024, 0x11);
  ReplyReader reader(4096);
  const auto before = test::allocations();
  std::size_t used = 0;
  std::size_t feeds = 0;
  while (used < stream.size() && reader.state() != ReplyReader::State::GaveUp && feeds < stream.size()) {
    used += reader.feed({stream.data() + used, stream.size() - used});
    ++feeds;
  }
  EXPECT_EQ(test::allocations().calls, before.calls) << "the claimed length was allocated";
  EXPECT_EQ(reader.state(), ReplyReader::State::GaveUp) << "waited for the bytes the length claimed";
  EXPECT_LE(reader.junk_bytes(), 4096u + 8u);
  EXPECT_FALSE(reader.complete());
}

TEST(LyingDevice, AnLsnOf255OverAShortPacketCostsOnlyThatPacket) {
  // Each lying packet claims 255 samples (510 bytes) but 20 bytes follow before a real packet;
  // the decoder must find the real packets again and allocate nothing per lie.
  const ModelProfile& g6 = profile_for(Model::G6);
  Bytes stream = test::synthetic_stream(1, 4, 40);  // warms the lap buffers
  for (int i = 0; i < 2000; ++i) {
    const Bytes liar{0xAA, 0x55, 0x00, 0xFF, 0x01, 0x00, 0x01, 0x00, 0x00, 0x00};
    stream.insert(stream.end(), liar.begin(), liar.end());
    stream.insert(stream.end(), 20, 0x33);
  }
  test::append(stream, test::synthetic_stream(3, 4, 40));
  ScanDecoder decoder(g6);
  std::uint64_t laps = 0;
  std::size_t most_points = 0;
  const auto before = test::allocations();
  decoder.feed(stream, 0, [&](const Lap& lap) {
    ++laps;
    most_points = std::max(most_points, lap.points.size());
  });
  decoder.finish([&](const Lap&) { ++laps; });
  EXPECT_EQ(test::allocations().calls, before.calls);
  EXPECT_GE(laps, 3u) << "the real laps after the lies were lost";
  EXPECT_LE(most_points, Lap::kMaxPoints);
  const DecoderCounters counters = decoder.counters();
  EXPECT_EQ(counters.bytes, stream.size());
}

TEST(LyingDevice, AnLsnOfZeroIsAPacketWithoutSamples) {
  Bytes stream = test::synthetic_stream(2, 4, 40);
  const Bytes empty{0xAA, 0x55, 0x00, 0x00, 0x01, 0x00, 0x01, 0x00, 0x55, 0xAA ^ 0x00};
  for (int i = 0; i < 100; ++i) stream.insert(stream.end(), empty.begin(), empty.end());
  test::append(stream, test::synthetic_stream(2, 4, 40));
  const auto decoded = test::decode(profile_for(Model::G6), stream);
  EXPECT_GE(decoded.laps.size(), 3u);
  for (const Lap& lap : decoded.laps) EXPECT_LE(lap.points.size(), Lap::kMaxPoints);
}

TEST(LyingDevice, RangingCodesOutsideTheTableAreNoFrequency) {
  for (const ModelProfile& profile : all_profiles()) {
    for (int code = 0; code < 256; ++code) {
      const std::uint8_t payload[1] = {static_cast<std::uint8_t>(code)};
      const auto khz = parse_ranging_khz(profile, payload);
      if (static_cast<std::size_t>(code) < profile.ranging_khz.size()) {
        ASSERT_TRUE(khz.has_value()) << profile.name << " code " << code;
        EXPECT_EQ(*khz, profile.ranging_khz[static_cast<std::size_t>(code)]);
      } else if (khz) {
        EXPECT_TRUE(profile.ranging_index(*khz).has_value()) << profile.name << " code " << code << " gave " << *khz;
      }
    }
  }
}

TEST(LyingDevice, FirmwareFieldsOfAnyValueGiveBoundedText) {
  for (int value = 0; value < 256; ++value) {
    DeviceInfo info;
    info.model_code = static_cast<std::uint8_t>(value);
    info.firmware_major = static_cast<std::uint8_t>(value);
    info.firmware_minor = static_cast<std::uint8_t>(255 - value);
    info.hardware = static_cast<std::uint8_t>(value);
    info.serial.fill(static_cast<std::uint8_t>(value));
    const auto encoded = encode_device_info(info);
    const auto parsed = parse_device_info(encoded);
    ASSERT_TRUE(parsed.has_value()) << value;
    EXPECT_LE(serial_string(*parsed).size(), 2 * info.serial.size()) << value;
    if (const ModelProfile* profile = find_profile_by_code(info.model_code)) {
      EXPECT_EQ(profile->model_code, info.model_code);
    }
  }
}

class LyingRecording : public ::testing::Test {
 protected:
  void TearDown() override { std::filesystem::remove(path_); }
  std::string write(const Bytes& bytes) {
    test::write_file_bytes(path_, bytes);
    return path_;
  }
  test::TempDir dir_{"lying-recording"};
  std::string path_ = dir_.file("lying.ydrec");
};

TEST_F(LyingRecording, ARecordLengthOf4GiBIsAnErrorNotAnAllocation) {
  test::RawRecording recording;
  Bytes bytes = recording.bytes();
  RecordHeader header;
  header.type = static_cast<std::uint8_t>(RecordType::DeviceToHost);
  header.length = 0xFFFFFFFF;
  const auto head = encode_record_header(header);
  bytes.insert(bytes.end(), head.begin(), head.end());
  bytes.resize(bytes.size() + 1000, 0x22);
  std::string error;
  test::reset_largest_allocation();
  auto reader = RecordingReader::open(write(bytes), error);
  ASSERT_TRUE(reader) << error;
  RecordView record;
  std::size_t records = 0;
  while (reader->next(record)) records += record.type == RecordType::DeviceToHost;
  EXPECT_EQ(records, 0u);
  EXPECT_TRUE(reader->corrupt()) << reader->warning();
  EXPECT_FALSE(reader->error().empty());
  EXPECT_LT(test::allocations().largest, 2u * kMaxRecordPayload);
}

TEST_F(LyingRecording, ARecordClaimingTheLargestPayloadInAShortFileIsACutOffTail) {
  test::RawRecording recording;
  recording.add_device_records({1000, 2000});
  Bytes bytes = recording.bytes();
  RecordHeader header;
  header.type = static_cast<std::uint8_t>(RecordType::DeviceToHost);
  header.length = kMaxRecordPayload;
  header.t_ns = 3000;
  const auto head = encode_record_header(header);
  bytes.insert(bytes.end(), head.begin(), head.end());
  bytes.resize(bytes.size() + 100, 0x22);
  std::string error;
  test::reset_largest_allocation();
  auto reader = RecordingReader::open(write(bytes), error);
  ASSERT_TRUE(reader) << error;
  RecordView record;
  std::size_t records = 0;
  while (reader->next(record)) records += record.type == RecordType::DeviceToHost;
  EXPECT_EQ(records, 2u);
  EXPECT_TRUE(reader->truncated()) << reader->error();
  EXPECT_LE(test::allocations().largest, kMaxRecordPayload + 4096u);
}

TEST_F(LyingRecording, AHeaderSizeOf64KiBIsRefusedWithoutReadingIt) {
  test::RawRecording recording(1, 0xFFFF);
  Bytes bytes = recording.bytes();
  bytes.resize(70000, 0x00);  // long enough that the claimed header would fit
  std::string error;
  RecordingOpenFailure failure = RecordingOpenFailure::Unreadable;
  test::reset_largest_allocation();
  EXPECT_FALSE(RecordingReader::open(write(bytes), error, &failure));
  EXPECT_EQ(failure, RecordingOpenFailure::Unsupported) << error;
  EXPECT_NE(error.find("65535"), std::string::npos) << error;
  EXPECT_LT(test::allocations().largest, 64u * 1024u);
}

}  // namespace
}  // namespace ydscope
