// McapWriter against the strict test reader: records, CRCs, indexes and summary agree, for every
// compression; chunks close by size and by time; a cut-off file keeps its finished chunks.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "core/export/mcap_writer.h"
#include "export/mcap_test_reader.h"

namespace ydscope {
namespace {

std::vector<std::uint8_t> payload(std::size_t n, std::uint8_t seed) {
  std::vector<std::uint8_t> p(n);
  for (std::size_t i = 0; i < n; ++i) p[i] = static_cast<std::uint8_t>(seed + i * 7);
  return p;
}

class McapWriterCompression : public ::testing::TestWithParam<ChunkCompression> {};

TEST_P(McapWriterCompression, EveryRecordAndIndexAgreesWithTheSpec) {
  McapMemorySink sink;
  McapWriterOptions options;
  options.compression = GetParam();
  options.chunk_size = 4000;  // several chunks
  McapWriter writer(sink, options);
  const std::string schema_text = "int32 x\n";
  const auto schema = writer.add_schema(
      "pkg/msg/A", "ros2msg", {reinterpret_cast<const std::uint8_t*>(schema_text.data()), schema_text.size()});
  const auto a = writer.add_channel(schema, "/a", "cdr", {{"k", "v"}});
  const auto b = writer.add_channel(schema, "/b", "cdr", {});
  ASSERT_TRUE(writer.write_metadata("ydscope.recording", {{"model", "G6"}}));
  for (std::uint32_t i = 0; i < 100; ++i)
    ASSERT_TRUE(writer.write_message(i % 3 ? a : b, i, 1'000'000'000ull + i * 1000, 1'000'000'000ull + i * 1000,
                                     payload(100 + i, static_cast<std::uint8_t>(i))));
  ASSERT_TRUE(writer.close());

  const auto contents = test::read_mcap(sink.bytes());
  EXPECT_TRUE(contents.complete);
  EXPECT_EQ(contents.profile, "ros2");
  ASSERT_EQ(contents.messages.size(), 100u);
  for (std::uint32_t i = 0; i < 100; ++i) {
    EXPECT_EQ(contents.messages[i].sequence, i);
    EXPECT_EQ(contents.messages[i].channel_id, i % 3 ? a : b);
    EXPECT_EQ(contents.messages[i].data, payload(100 + i, static_cast<std::uint8_t>(i)));
  }
  EXPECT_GT(contents.chunks, 2u);
  EXPECT_EQ(contents.stat_chunks, contents.chunks);
  EXPECT_EQ(contents.chunk_indexes, contents.chunks);
  EXPECT_EQ(contents.stat_messages, 100u);
  EXPECT_EQ(contents.stat_schemas, 1u);
  EXPECT_EQ(contents.stat_channels, 2u);
  EXPECT_EQ(contents.stat_metadata, 1u);
  EXPECT_EQ(contents.stat_start, 1'000'000'000ull);
  EXPECT_EQ(contents.stat_end, 1'000'000'000ull + 99 * 1000);
  EXPECT_EQ(contents.stat_channel_counts.at(a), 66u);
  EXPECT_EQ(contents.stat_channel_counts.at(b), 34u);
  EXPECT_EQ(contents.channels.at(a).metadata.at("k"), "v");
  ASSERT_EQ(contents.metadata.size(), 1u);
  EXPECT_EQ(contents.metadata[0].at("model"), "G6");
}

INSTANTIATE_TEST_SUITE_P(AllCompressions, McapWriterCompression,
                         ::testing::Values(ChunkCompression::None, ChunkCompression::Zstd, ChunkCompression::Lz4));

TEST(McapWriter, AFileWithoutMessagesIsStillComplete) {
  McapMemorySink sink;
  McapWriter writer(sink);
  ASSERT_TRUE(writer.close());
  const auto contents = test::read_mcap(sink.bytes());
  EXPECT_TRUE(contents.complete);
  EXPECT_EQ(contents.chunks, 0u);
  EXPECT_EQ(contents.stat_messages, 0u);
}

TEST(McapWriter, AChunkNeverSpansMoreThanItsTimeLimit) {
  McapMemorySink sink;
  McapWriter writer(sink);  // 1 s span, 1 MiB: only time closes these chunks
  const auto s = writer.add_schema("pkg/msg/A", "ros2msg", {});
  const auto ch = writer.add_channel(s, "/a", "cdr", {});
  for (int i = 0; i < 50; ++i)  // 10 Hz for 5 s
    ASSERT_TRUE(writer.write_message(ch, 0, static_cast<std::uint64_t>(i) * 100'000'000ull,
                                     static_cast<std::uint64_t>(i) * 100'000'000ull, payload(10, 1)));
  ASSERT_TRUE(writer.close());
  const auto contents = test::read_mcap(sink.bytes());
  EXPECT_EQ(contents.messages.size(), 50u);
  EXPECT_GE(contents.chunks, 5u);
  EXPECT_LE(contents.chunks, 6u);
}

TEST(McapWriter, ACutOffFileKeepsEveryFlushedChunk) {
  McapMemorySink sink;
  McapWriter writer(sink);
  const auto s = writer.add_schema("pkg/msg/A", "ros2msg", {});
  const auto ch = writer.add_channel(s, "/a", "cdr", {});
  for (int i = 0; i < 10; ++i) ASSERT_TRUE(writer.write_message(ch, 0, 5, 5, payload(64, 2)));
  ASSERT_TRUE(writer.flush_chunk());
  const std::size_t flushed = sink.bytes().size();
  for (int i = 0; i < 10; ++i) ASSERT_TRUE(writer.write_message(ch, 0, 6, 6, payload(64, 3)));
  ASSERT_TRUE(writer.flush_chunk());
  // Killed in the middle of writing the second chunk:
  std::vector<std::uint8_t> cut(sink.bytes().begin(), sink.bytes().begin() + static_cast<std::ptrdiff_t>(flushed + 30));
  const auto contents = test::read_mcap(cut);
  EXPECT_FALSE(contents.complete);
  EXPECT_EQ(contents.messages.size(), 10u);
}

TEST(McapWriter, AMessageOnAnUnknownChannelIsRefusedWithAReason) {
  McapMemorySink sink;
  McapWriter writer(sink);
  EXPECT_FALSE(writer.write_message(3, 0, 0, 0, payload(4, 0)));
  EXPECT_NE(writer.error().find("channel 3"), std::string::npos);
}

}  // namespace
}  // namespace ydscope
