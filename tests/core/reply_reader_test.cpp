// ReplyReader: junk before the reply, byte-by-byte arrival, bounded lengths, bytes after the reply.
#include <gtest/gtest.h>

#include "core/protocol/reply_reader.h"

namespace ydscope {
namespace {

using Bytes = std::vector<std::uint8_t>;

TEST(ReplyReader, SkipsJunkAndStopsRightAfterTheReply) {
  Bytes stream{0x00, 0xA5, 0x11, 0xA5};  // junk, including a lone A5 and an A5 that is not followed by 5A
  const auto reply = encode_reply(Command::ScanHzGet, encode_scan_frequency({850}));
  stream.insert(stream.end(), reply.begin(), reply.end());
  stream.push_back(0xAA);  // belongs to the caller
  ReplyReader reader;
  const std::size_t used = reader.feed(stream);
  ASSERT_TRUE(reader.complete());
  EXPECT_EQ(used, stream.size() - 1);
  EXPECT_EQ(reader.junk_bytes(), 4u);
  EXPECT_TRUE(reply_matches(reader.header(), Command::ScanHzGet));
  EXPECT_EQ(parse_scan_frequency(reader.payload())->centihertz, 850u);
}

TEST(ReplyReader, ByteByByte) {
  const auto info = encode_device_info({19, 1, 2, 3, {}});
  const auto reply = encode_reply(Command::DeviceInfo, info);
  ReplyReader reader;
  for (std::size_t i = 0; i < reply.size(); ++i) {
    EXPECT_FALSE(reader.complete()) << i;
    EXPECT_EQ(reader.feed({reply.data() + i, 1}), 1u);
  }
  ASSERT_TRUE(reader.complete());
  EXPECT_EQ(parse_device_info(reader.payload())->model_code, 19);
  EXPECT_EQ(reader.feed(reply), 0u);  // complete: takes nothing more until reset
  reader.reset();
  EXPECT_EQ(reader.feed(reply), reply.size());
  EXPECT_TRUE(reader.complete());
}

TEST(ReplyReader, ScanReplyLeavesThePacketsToTheCaller) {
  Bytes stream{0xA5, 0x5A, 0x05, 0x00, 0x00, 0x40, 0x81, 0xAA, 0x55};
  ReplyReader reader;
  EXPECT_EQ(reader.feed(stream), 7u);
  ASSERT_TRUE(reader.complete());
  EXPECT_TRUE(reply_matches(reader.header(), Command::Scan));
  EXPECT_TRUE(reader.payload().empty());
}

TEST(ReplyReader, OversizedLengthIsJunkNotAnAllocation) {
  // A5 5A FF A5 5A 01 00 claims 0x015AA5FF payload bytes; the real reply starts inside that fake header.
  Bytes stream{0xA5, 0x5A, 0xFF, 0xA5, 0x5A, 0x01, 0x00, 0x00, 0x00, 0x04, 0x02};
  ReplyReader reader;
  EXPECT_EQ(reader.feed(stream), stream.size());
  ASSERT_TRUE(reader.complete());
  EXPECT_EQ(reader.header().length, 1u);
  EXPECT_EQ(reader.payload()[0], 0x02);
  EXPECT_EQ(reader.junk_bytes(), 3u);
}

TEST(ReplyReader, GivesUpAfterTooMuchJunk) {
  ReplyReader reader(16);
  const Bytes junk(100, 0x11);
  reader.feed(junk);
  EXPECT_EQ(reader.state(), ReplyReader::State::GaveUp);
}

}  // namespace
}  // namespace ydscope
