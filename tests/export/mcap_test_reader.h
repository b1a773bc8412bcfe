#pragma once
// A strict MCAP reader for the tests, written from the specification independently of the
// writer's code: it walks every record, checks every CRC and every index against the records it
// points to, and collects the messages. A violation throws with what was wrong and where.
#include <lz4frame.h>
#include <zlib.h>
#include <zstd.h>

#include <cstdint>
#include <cstring>
#include <map>
#include <stdexcept>
#include <string>
#include <vector>

namespace ydscope::test {

struct ReadMessage {
  std::uint16_t channel_id;
  std::uint32_t sequence;
  std::uint64_t log_time;
  std::vector<std::uint8_t> data;
};

struct ReadChannel {
  std::uint16_t schema_id;
  std::string topic, encoding;
  std::map<std::string, std::string> metadata;
};

struct ReadSchema {
  std::string name, encoding, data;
};

struct McapContents {
  std::string profile, library;
  std::map<std::uint16_t, ReadSchema> schemas;
  std::map<std::uint16_t, ReadChannel> channels;
  std::vector<ReadMessage> messages;
  std::vector<std::map<std::string, std::string>> metadata;
  std::uint32_t chunks = 0;
  bool complete = false;  // footer and trailing magic present and valid
  // From the summary (when complete).
  std::uint64_t stat_messages = 0, stat_start = 0, stat_end = 0;
  std::uint32_t stat_chunks = 0, stat_channels = 0, stat_metadata = 0;
  std::uint16_t stat_schemas = 0;
  std::map<std::uint16_t, std::uint64_t> stat_channel_counts;
  std::uint32_t chunk_indexes = 0;
};

class McapCursor {
 public:
  McapCursor(const std::uint8_t* p, std::size_t n) : p_(p), n_(n) {}
  std::size_t left() const { return n_ - at_; }
  std::size_t offset() const { return at_; }
  void need(std::size_t k) const {
    if (left() < k) throw std::runtime_error("record runs past its end at " + std::to_string(at_));
  }
  std::uint64_t le(int k) {
    need(static_cast<std::size_t>(k));
    std::uint64_t v = 0;
    for (int i = 0; i < k; ++i) v |= static_cast<std::uint64_t>(p_[at_ + static_cast<std::size_t>(i)]) << (8 * i);
    at_ += static_cast<std::size_t>(k);
    return v;
  }
  std::string str() {
    const auto len = static_cast<std::size_t>(le(4));
    need(len);
    std::string s(reinterpret_cast<const char*>(p_ + at_), len);
    at_ += len;
    return s;
  }
  std::vector<std::uint8_t> bytes(std::size_t len) {
    need(len);
    std::vector<std::uint8_t> b(p_ + at_, p_ + at_ + len);
    at_ += len;
    return b;
  }
  std::map<std::string, std::string> string_map() {
    const auto len = static_cast<std::size_t>(le(4));
    const std::size_t end = at_ + len;
    std::map<std::string, std::string> m;
    while (at_ < end) {
      std::string k = str();
      m[k] = str();
    }
    if (at_ != end) throw std::runtime_error("map length mismatch");
    return m;
  }

 private:
  const std::uint8_t* p_;
  std::size_t n_;
  std::size_t at_ = 0;
};

inline std::uint32_t test_crc32(const std::uint8_t* p, std::size_t n) {
  return static_cast<std::uint32_t>(::crc32(0, p, static_cast<uInt>(n)));
}

inline std::vector<std::uint8_t> decompress(const std::string& compression, const std::vector<std::uint8_t>& in,
                                            std::uint64_t size) {
  std::vector<std::uint8_t> out(size);
  if (compression.empty()) return in;
  if (compression == "zstd") {
    const std::size_t n = ZSTD_decompress(out.data(), out.size(), in.data(), in.size());
    if (ZSTD_isError(n) || n != size) throw std::runtime_error("zstd chunk does not decompress to its size");
    return out;
  }
  if (compression == "lz4") {
    LZ4F_dctx* ctx = nullptr;
    LZ4F_createDecompressionContext(&ctx, LZ4F_VERSION);
    std::size_t out_size = out.size(), in_size = in.size();
    const std::size_t r = LZ4F_decompress(ctx, out.data(), &out_size, in.data(), &in_size, nullptr);
    LZ4F_freeDecompressionContext(ctx);
    if (LZ4F_isError(r) || out_size != size) throw std::runtime_error("lz4 chunk does not decompress to its size");
    return out;
  }
  throw std::runtime_error("unknown compression " + compression);
}

// Reads a whole file (or a truncated one: then complete stays false and what was readable is kept).
inline McapContents read_mcap(const std::vector<std::uint8_t>& file) {
  static const std::uint8_t kMagic[8] = {0x89, 'M', 'C', 'A', 'P', 0x30, '\r', '\n'};
  McapContents out;
  if (file.size() < 8 || std::memcmp(file.data(), kMagic, 8) != 0) throw std::runtime_error("no leading magic");
  McapCursor c(file.data(), file.size());
  c.le(8);
  bool first = true, data_end = false;
  std::size_t summary_start = 0;
  // Per chunk at file offset: the message-record offsets in its uncompressed records, by channel.
  std::map<std::uint64_t, std::map<std::uint16_t, std::vector<std::pair<std::uint64_t, std::uint64_t>>>> chunk_messages;
  std::uint64_t last_chunk = 0;
  std::map<std::uint64_t, std::uint64_t> message_index_at;  // file offset -> channel
  while (c.left() > 0) {
    const std::size_t record_at = c.offset();
    if (c.left() < 9) break;  // truncated
    const auto op = static_cast<std::uint8_t>(c.le(1));
    const auto len = c.le(8);
    if (c.left() < len) break;  // truncated inside a record
    const std::size_t content_at = c.offset();
    McapCursor r(file.data() + content_at, static_cast<std::size_t>(len));
    c.bytes(static_cast<std::size_t>(len));
    if (first && op != 0x01) throw std::runtime_error("first record is not a Header");
    first = false;
    if (data_end && op != 0x02 && op != 0x03 && op != 0x04 && op != 0x08 && op != 0x0B && op != 0x0D && op != 0x0E)
      throw std::runtime_error("record " + std::to_string(op) + " in the summary section");
    switch (op) {
      case 0x01:
        out.profile = r.str();
        out.library = r.str();
        break;
      case 0x03: {
        const auto id = static_cast<std::uint16_t>(r.le(2));
        ReadSchema s{r.str(), r.str(), {}};
        const auto n = static_cast<std::size_t>(r.le(4));
        const auto b = r.bytes(n);
        s.data.assign(b.begin(), b.end());
        if (!data_end)
          out.schemas[id] = s;
        else if (out.schemas.at(id).data != s.data)
          throw std::runtime_error("summary schema differs");
        if (data_end) ++out.stat_schemas;
        break;
      }
      case 0x04: {
        const auto id = static_cast<std::uint16_t>(r.le(2));
        ReadChannel ch;
        ch.schema_id = static_cast<std::uint16_t>(r.le(2));
        ch.topic = r.str();
        ch.encoding = r.str();
        ch.metadata = r.string_map();
        if (!out.schemas.count(ch.schema_id)) throw std::runtime_error("channel before its schema");
        if (!data_end) out.channels[id] = ch;
        break;
      }
      case 0x06: {
        const auto start = r.le(8), end = r.le(8), size = r.le(8);
        const auto crc = static_cast<std::uint32_t>(r.le(4));
        const std::string compression = r.str();
        const auto n = static_cast<std::size_t>(r.le(8));
        const auto records = decompress(compression, r.bytes(n), size);
        if (crc != test_crc32(records.data(), records.size())) throw std::runtime_error("chunk CRC mismatch");
        ++out.chunks;
        last_chunk = record_at;
        McapCursor m(records.data(), records.size());
        while (m.left() > 0) {
          const std::size_t at = m.offset();
          const auto mop = m.le(1);
          const auto mlen = static_cast<std::size_t>(m.le(8));
          McapCursor body(records.data() + m.offset(), mlen);
          m.bytes(mlen);
          if (mop != 0x05) continue;
          ReadMessage msg;
          msg.channel_id = static_cast<std::uint16_t>(body.le(2));
          msg.sequence = static_cast<std::uint32_t>(body.le(4));
          msg.log_time = body.le(8);
          if (body.le(8) != msg.log_time) throw std::runtime_error("publish_time differs from log_time");
          msg.data = body.bytes(body.left());
          if (!out.channels.count(msg.channel_id)) throw std::runtime_error("message before its channel");
          if (msg.log_time < start || msg.log_time > end) throw std::runtime_error("message outside its chunk's times");
          chunk_messages[record_at][msg.channel_id].emplace_back(msg.log_time, at);
          out.messages.push_back(std::move(msg));
        }
        break;
      }
      case 0x07: {
        const auto channel = static_cast<std::uint16_t>(r.le(2));
        const auto n = static_cast<std::size_t>(r.le(4)) / 16;
        std::vector<std::pair<std::uint64_t, std::uint64_t>> entries;
        for (std::size_t i = 0; i < n; ++i) {
          const auto t = r.le(8);
          entries.emplace_back(t, r.le(8));
        }
        if (chunk_messages[last_chunk][channel] != entries)
          throw std::runtime_error("message index disagrees with its chunk");
        message_index_at[record_at] = channel;
        break;
      }
      case 0x0C: {
        r.str();
        out.metadata.push_back(r.string_map());
        break;
      }
      case 0x0F: {
        const auto crc = static_cast<std::uint32_t>(r.le(4));
        if (crc != test_crc32(file.data(), record_at)) throw std::runtime_error("data section CRC mismatch");
        data_end = true;
        summary_start = c.offset();
        break;
      }
      case 0x0B: {
        out.stat_messages = r.le(8);
        r.le(2);
        out.stat_channels = static_cast<std::uint32_t>(r.le(4));
        r.le(4);
        out.stat_metadata = static_cast<std::uint32_t>(r.le(4));
        out.stat_chunks = static_cast<std::uint32_t>(r.le(4));
        out.stat_start = r.le(8);
        out.stat_end = r.le(8);
        const auto n = static_cast<std::size_t>(r.le(4)) / 10;
        for (std::size_t i = 0; i < n; ++i) {
          const auto id = static_cast<std::uint16_t>(r.le(2));
          out.stat_channel_counts[id] = r.le(8);
        }
        break;
      }
      case 0x08: {
        r.le(8);
        r.le(8);
        const auto chunk_at = r.le(8);
        r.le(8);
        if (!chunk_messages.count(chunk_at) && file[chunk_at] != 0x06)
          throw std::runtime_error("chunk index points at no chunk");
        if (file[chunk_at] != 0x06) throw std::runtime_error("chunk index points at no chunk");
        const auto n = static_cast<std::size_t>(r.le(4)) / 10;
        for (std::size_t i = 0; i < n; ++i) {
          const auto id = static_cast<std::uint16_t>(r.le(2));
          const auto at = r.le(8);
          if (!message_index_at.count(at) || message_index_at[at] != id)
            throw std::runtime_error("chunk index's message index offset is wrong");
        }
        ++out.chunk_indexes;
        break;
      }
      case 0x0E: {
        const auto group = static_cast<std::uint8_t>(r.le(1));
        const auto start = r.le(8);
        if (file[start] != group) throw std::runtime_error("summary offset points at another opcode");
        break;
      }
      case 0x02: {
        const auto start = r.le(8);
        r.le(8);
        const auto crc = static_cast<std::uint32_t>(r.le(4));
        if (start != summary_start) throw std::runtime_error("footer summary_start is wrong");
        if (crc != test_crc32(file.data() + start, c.offset() - 4 - start))
          throw std::runtime_error("summary CRC mismatch");
        if (c.left() != 8 || std::memcmp(file.data() + c.offset(), kMagic, 8) != 0)
          throw std::runtime_error("no trailing magic");
        out.complete = true;
        return out;
      }
      default: break;
    }
  }
  return out;
}

}  // namespace ydscope::test
