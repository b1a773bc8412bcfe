#include "core/export/mcap_writer.h"

#include <algorithm>
#include <array>

namespace ydscope {
namespace {

constexpr std::array<std::uint8_t, 8> kMagic = {0x89, 'M', 'C', 'A', 'P', 0x30, '\r', '\n'};

enum Opcode : std::uint8_t {
  kHeader = 0x01,
  kFooter = 0x02,
  kSchema = 0x03,
  kChannel = 0x04,
  kMessage = 0x05,
  kChunk = 0x06,
  kMessageIndex = 0x07,
  kChunkIndex = 0x08,
  kStatistics = 0x0B,
  kMetadata = 0x0C,
  kMetadataIndex = 0x0D,
  kSummaryOffset = 0x0E,
  kDataEnd = 0x0F,
};

void put_string_map(ByteBuffer& out, const McapMetadataMap& map) {
  const std::size_t length_at = out.reserve_u32();
  for (const auto& [key, value] : map) {
    out.string(key);
    out.string(value);
  }
  out.patch_u32(length_at, static_cast<std::uint32_t>(out.size() - length_at - 4));
}

void put_schema(ByteBuffer& out, std::uint16_t id, std::string_view name, std::string_view encoding,
                std::span<const std::uint8_t> data) {
  out.u16(id);
  out.string(name);
  out.string(encoding);
  out.u32(static_cast<std::uint32_t>(data.size()));
  out.raw(data);
}

void put_channel(ByteBuffer& out, std::uint16_t id, std::uint16_t schema_id, std::string_view topic,
                 std::string_view encoding, const McapMetadataMap& metadata) {
  out.u16(id);
  out.u16(schema_id);
  out.string(topic);
  out.string(encoding);
  put_string_map(out, metadata);
}

// <opcode><u64 length><content> appended to `out`.
void wrap_record(ByteBuffer& out, std::uint8_t opcode, const ByteBuffer& content) {
  out.u8(opcode);
  out.u64(content.size());
  out.raw(content.view());
}

}  // namespace

McapWriter::McapWriter(McapSink& sink, McapWriterOptions options) : sink_(sink), options_(std::move(options)) {
  emit(kMagic);
  scratch_.clear();
  scratch_.string(options_.profile);
  scratch_.string(options_.library);
  emit_record(kHeader, scratch_);
}

void McapWriter::fail(std::string why) {
  if (error_.empty()) error_ = std::move(why);
}

bool McapWriter::emit(std::span<const std::uint8_t> bytes, bool in_data_section) {
  if (!error_.empty()) return false;
  if (!sink_.write(bytes)) {
    fail(sink_.error().empty() ? "writing the MCAP file failed" : sink_.error());
    return false;
  }
  if (in_data_section) data_crc_ = crc32_update(data_crc_, bytes);
  offset_ += bytes.size();
  return true;
}

bool McapWriter::emit_record(std::uint8_t opcode, ByteBuffer& record, bool in_data_section) {
  std::array<std::uint8_t, 9> head{};
  head[0] = opcode;
  for (int i = 0; i < 8; ++i) head[1 + i] = static_cast<std::uint8_t>(record.size() >> (8 * i));
  return emit(head, in_data_section) && emit(record.view(), in_data_section);
}

std::uint16_t McapWriter::add_schema(std::string_view name, std::string_view encoding,
                                     std::span<const std::uint8_t> data) {
  const auto id = static_cast<std::uint16_t>(schemas_.size() + 1);
  schemas_.push_back({id, std::string(name), std::string(encoding), {data.begin(), data.end()}});
  scratch_.clear();
  put_schema(scratch_, id, name, encoding, data);
  emit_record(kSchema, scratch_);
  return id;
}

std::uint16_t McapWriter::add_channel(std::uint16_t schema_id, std::string_view topic,
                                      std::string_view message_encoding, const McapMetadataMap& metadata) {
  const auto id = static_cast<std::uint16_t>(channels_.size() + 1);
  channels_.push_back({id, schema_id, std::string(topic), std::string(message_encoding), metadata});
  scratch_.clear();
  put_channel(scratch_, id, schema_id, topic, message_encoding, metadata);
  emit_record(kChannel, scratch_);
  return id;
}

bool McapWriter::write_message(std::uint16_t channel_id, std::uint32_t sequence, std::uint64_t log_time,
                               std::uint64_t publish_time, std::span<const std::uint8_t> data) {
  if (closed_) fail("the MCAP file is already closed");
  if (channel_id == 0 || channel_id > channels_.size())
    fail("message on channel " + std::to_string(channel_id) + ", which was never added");
  if (!error_.empty()) return false;
  // Close the chunk first if this message would stretch it past its time span.
  if (!chunk_.empty()) {
    const std::uint64_t start = std::min(chunk_start_time_, log_time);
    const std::uint64_t end = std::max(chunk_end_time_, log_time);
    if (end - start > options_.max_chunk_span_ns && !flush_chunk()) return false;
  }
  if (chunk_.empty()) chunk_start_time_ = chunk_end_time_ = log_time;
  chunk_start_time_ = std::min(chunk_start_time_, log_time);
  chunk_end_time_ = std::max(chunk_end_time_, log_time);
  chunk_message_index_[channel_id].emplace_back(log_time, chunk_.size());
  chunk_.u8(kMessage);
  chunk_.u64(2 + 4 + 8 + 8 + data.size());
  chunk_.u16(channel_id);
  chunk_.u32(sequence);
  chunk_.u64(log_time);
  chunk_.u64(publish_time);
  chunk_.raw(data);

  if (stats_.message_count == 0) stats_.message_start_time = stats_.message_end_time = log_time;
  stats_.message_start_time = std::min(stats_.message_start_time, log_time);
  stats_.message_end_time = std::max(stats_.message_end_time, log_time);
  ++stats_.message_count;
  ++stats_.channel_message_counts[channel_id];
  if (chunk_.size() >= options_.chunk_size) return flush_chunk();
  return true;
}

bool McapWriter::write_metadata(std::string_view name, const McapMetadataMap& metadata) {
  if (closed_) fail("the MCAP file is already closed");
  if (!error_.empty()) return false;
  scratch_.clear();
  scratch_.string(name);
  put_string_map(scratch_, metadata);
  const std::uint64_t at = offset_;
  if (!emit_record(kMetadata, scratch_)) return false;
  metadata_indexes_.push_back({at, offset_ - at, std::string(name)});
  ++stats_.metadata_count;
  return true;
}

bool McapWriter::flush_chunk() {
  if (!error_.empty()) return false;
  if (chunk_.empty()) return sink_.flush() || (fail(sink_.error()), false);
  std::string why;
  if (!compress_chunk(options_.compression, chunk_.view(), compressed_, why)) {
    fail(why);
    return false;
  }
  ChunkIndex index{};
  index.start_time = chunk_start_time_;
  index.end_time = chunk_end_time_;
  index.chunk_offset = offset_;
  index.compressed_size = compressed_.size();
  index.uncompressed_size = chunk_.size();

  scratch_.clear();
  scratch_.u64(chunk_start_time_);
  scratch_.u64(chunk_end_time_);
  scratch_.u64(chunk_.size());
  scratch_.u32(crc32_update(0, chunk_.view()));
  scratch_.string(compression_field(options_.compression));
  scratch_.u64(compressed_.size());
  // The records go out straight from compressed_ rather than through another copy.
  std::array<std::uint8_t, 9> head{};
  head[0] = kChunk;
  const std::uint64_t length = scratch_.size() + compressed_.size();
  for (int i = 0; i < 8; ++i) head[1 + i] = static_cast<std::uint8_t>(length >> (8 * i));
  if (!emit(head) || !emit(scratch_.view()) || !emit(compressed_)) return false;
  index.chunk_length = offset_ - index.chunk_offset;

  const std::uint64_t indexes_start = offset_;
  for (auto& [channel_id, entries] : chunk_message_index_) {
    scratch_.clear();
    scratch_.u16(channel_id);
    scratch_.u32(static_cast<std::uint32_t>(entries.size() * 16));
    for (const auto& [time, position] : entries) {
      scratch_.u64(time);
      scratch_.u64(position);
    }
    index.message_index_offsets[channel_id] = offset_;
    if (!emit_record(kMessageIndex, scratch_)) return false;
  }
  index.message_index_length = offset_ - indexes_start;
  chunk_indexes_.push_back(std::move(index));
  ++stats_.chunk_count;
  chunk_.clear();
  chunk_message_index_.clear();
  if (!sink_.flush()) {
    fail(sink_.error());
    return false;
  }
  return true;
}

bool McapWriter::close() {
  if (closed_) return error_.empty();
  if (!flush_chunk()) {
    closed_ = true;
    return false;
  }
  closed_ = true;
  scratch_.clear();
  scratch_.u32(data_crc_);
  if (!emit_record(kDataEnd, scratch_)) return false;

  // Summary section, grouped by opcode; each group gets a Summary Offset record.
  ByteBuffer summary;
  const std::uint64_t summary_start = offset_;
  struct Group {
    std::uint8_t opcode;
    std::uint64_t start, length;
  };
  std::vector<Group> groups;
  ByteBuffer content;
  const auto group = [&](std::uint8_t opcode, auto&& each) {
    const std::uint64_t start = summary_start + summary.size();
    each();
    const std::uint64_t length = summary_start + summary.size() - start;
    if (length > 0) groups.push_back({opcode, start, length});
  };
  group(kSchema, [&] {
    for (const auto& s : schemas_) {
      content.clear();
      put_schema(content, s.id, s.name, s.encoding, s.data);
      wrap_record(summary, kSchema, content);
    }
  });
  group(kChannel, [&] {
    for (const auto& c : channels_) {
      content.clear();
      put_channel(content, c.id, c.schema_id, c.topic, c.message_encoding, c.metadata);
      wrap_record(summary, kChannel, content);
    }
  });
  group(kStatistics, [&] {
    content.clear();
    content.u64(stats_.message_count);
    content.u16(static_cast<std::uint16_t>(schemas_.size()));
    content.u32(static_cast<std::uint32_t>(channels_.size()));
    content.u32(0);  // attachments
    content.u32(stats_.metadata_count);
    content.u32(stats_.chunk_count);
    content.u64(stats_.message_start_time);
    content.u64(stats_.message_end_time);
    content.u32(static_cast<std::uint32_t>(stats_.channel_message_counts.size() * 10));
    for (const auto& [id, count] : stats_.channel_message_counts) {
      content.u16(id);
      content.u64(count);
    }
    wrap_record(summary, kStatistics, content);
  });
  group(kChunkIndex, [&] {
    for (const auto& c : chunk_indexes_) {
      content.clear();
      content.u64(c.start_time);
      content.u64(c.end_time);
      content.u64(c.chunk_offset);
      content.u64(c.chunk_length);
      content.u32(static_cast<std::uint32_t>(c.message_index_offsets.size() * 10));
      for (const auto& [id, offset] : c.message_index_offsets) {
        content.u16(id);
        content.u64(offset);
      }
      content.u64(c.message_index_length);
      content.string(compression_field(options_.compression));
      content.u64(c.compressed_size);
      content.u64(c.uncompressed_size);
      wrap_record(summary, kChunkIndex, content);
    }
  });
  group(kMetadataIndex, [&] {
    for (const auto& m : metadata_indexes_) {
      content.clear();
      content.u64(m.offset);
      content.u64(m.length);
      content.string(m.name);
      wrap_record(summary, kMetadataIndex, content);
    }
  });
  const std::uint64_t summary_offset_start = summary_start + summary.size();
  for (const auto& g : groups) {
    content.clear();
    content.u8(g.opcode);
    content.u64(g.start);
    content.u64(g.length);
    wrap_record(summary, kSummaryOffset, content);
  }
  // Footer: the summary CRC covers the summary, the summary offsets and the footer up to its CRC field.
  summary.u8(kFooter);
  summary.u64(8 + 8 + 4);
  summary.u64(summary_start);
  summary.u64(summary_offset_start);
  summary.u32(crc32_update(0, summary.view()));
  summary.raw(kMagic);
  if (!emit(summary.view(), false)) return false;
  if (!sink_.flush()) fail(sink_.error());
  return error_.empty();
}

}  // namespace ydscope
