#pragma once
// McapWriter: a spec-complete MCAP writer (https://mcap.dev/spec), version 0 of the format.
//
// File shape: magic, Header, then the data section: Schema and Channel records as they are
// added, Metadata records, and Chunks (each followed by one Message Index per channel in it);
// then DataEnd (with the data section's CRC32), the summary section grouped by opcode (Schemas,
// Channels, Statistics, Chunk Indexes, Metadata Indexes), Summary Offsets, Footer (summary CRC32)
// and the magic again. Every chunk carries the CRC32 of its uncompressed records.
//
// Durability: a chunk is closed (compressed, written and flushed to the sink) when it holds
// chunk_size bytes or spans max_chunk_span_ns of log time, and whenever flush_chunk() is called
// (a live recorder calls it at least once a second), so a killed writer leaves a file whose
// finished chunks a streaming reader recovers. Not thread-safe: one thread owns a writer.
#include <cstdint>
#include <map>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "core/export/byte_buffer.h"
#include "core/export/chunk_compression.h"
#include "core/export/mcap_sink.h"

namespace ydscope {

struct McapWriterOptions {
  std::string profile = "ros2";
  std::string library = "ydscope 0.1.0";
  ChunkCompression compression = ChunkCompression::Zstd;
  std::size_t chunk_size = 1 << 20;                 // uncompressed bytes of records per chunk
  std::uint64_t max_chunk_span_ns = 1'000'000'000;  // log-time span of one chunk
};

using McapMetadataMap = std::map<std::string, std::string>;

struct McapStatistics {
  std::uint64_t message_count = 0;
  std::uint32_t chunk_count = 0;
  std::uint32_t metadata_count = 0;
  std::uint64_t message_start_time = 0;
  std::uint64_t message_end_time = 0;
  std::map<std::uint16_t, std::uint64_t> channel_message_counts;
};

class McapWriter {
 public:
  // Writes the magic and the Header record to `sink` (which must outlive the writer).
  McapWriter(McapSink& sink, McapWriterOptions options = {});
  ~McapWriter() = default;
  McapWriter(const McapWriter&) = delete;
  McapWriter& operator=(const McapWriter&) = delete;

  // Ids start at 1 and are written to the data section at once.
  std::uint16_t add_schema(std::string_view name, std::string_view encoding, std::span<const std::uint8_t> data);
  std::uint16_t add_channel(std::uint16_t schema_id, std::string_view topic, std::string_view message_encoding,
                            const McapMetadataMap& metadata);
  // A message on a channel returned by add_channel (others are refused with an error).
  bool write_message(std::uint16_t channel_id, std::uint32_t sequence, std::uint64_t log_time,
                     std::uint64_t publish_time, std::span<const std::uint8_t> data);
  // A Metadata record in the data section (indexed in the summary).
  bool write_metadata(std::string_view name, const McapMetadataMap& metadata);
  // Closes the open chunk (if it holds anything) and flushes the sink.
  bool flush_chunk();
  // Finishes the file: last chunk, DataEnd, summary, summary offsets, footer, magic. Later calls
  // do nothing. False if anything failed (error()).
  bool close();

  bool failed() const { return !error_.empty(); }
  const std::string& error() const { return error_; }
  const McapStatistics& statistics() const { return stats_; }
  std::uint64_t bytes_written() const { return offset_; }

 private:
  struct Schema {
    std::uint16_t id;
    std::string name, encoding;
    std::vector<std::uint8_t> data;
  };
  struct Channel {
    std::uint16_t id, schema_id;
    std::string topic, message_encoding;
    McapMetadataMap metadata;
  };
  struct ChunkIndex {
    std::uint64_t start_time, end_time, chunk_offset, chunk_length;
    std::map<std::uint16_t, std::uint64_t> message_index_offsets;
    std::uint64_t message_index_length, compressed_size, uncompressed_size;
  };
  struct MetadataIndex {
    std::uint64_t offset, length;
    std::string name;
  };

  bool emit(std::span<const std::uint8_t> bytes, bool in_data_section = true);
  bool emit_record(std::uint8_t opcode, ByteBuffer& record, bool in_data_section = true);
  void fail(std::string why);

  McapSink& sink_;
  McapWriterOptions options_;
  std::vector<Schema> schemas_;
  std::vector<Channel> channels_;
  std::vector<ChunkIndex> chunk_indexes_;
  std::vector<MetadataIndex> metadata_indexes_;
  McapStatistics stats_;
  std::uint64_t offset_ = 0;
  std::uint32_t data_crc_ = 0;
  bool closed_ = false;
  std::string error_;

  // The open chunk: its records uncompressed, and per channel (log_time, offset) for its index.
  ByteBuffer chunk_;
  std::uint64_t chunk_start_time_ = 0;
  std::uint64_t chunk_end_time_ = 0;
  std::map<std::uint16_t, std::vector<std::pair<std::uint64_t, std::uint64_t>>> chunk_message_index_;
  std::vector<std::uint8_t> compressed_;
  ByteBuffer scratch_;
};

}  // namespace ydscope
