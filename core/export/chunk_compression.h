#pragma once
// The chunk compressions MCAP readers know (spec registry): none, zstd and lz4 (LZ4 frame format).
#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace ydscope {

enum class ChunkCompression : std::uint8_t { None, Zstd, Lz4 };

// "", "zstd" or "lz4": the Chunk record's compression field.
std::string_view compression_field(ChunkCompression compression);
// "none", "zstd" or "lz4" (command-line spelling); empty for anything else.
std::optional<ChunkCompression> parse_compression(std::string_view name);

// Compresses `input` into `output` (replaced). False plus a sentence in `error` if the library failed.
bool compress_chunk(ChunkCompression compression, std::span<const std::uint8_t> input,
                    std::vector<std::uint8_t>& output, std::string& error);

// CRC32 (zlib's, as MCAP uses) of `bytes`, continuing from `crc` (0 to start).
std::uint32_t crc32_update(std::uint32_t crc, std::span<const std::uint8_t> bytes);

}  // namespace ydscope
