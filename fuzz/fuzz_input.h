#pragma once
// What every fuzz target shares: a checked assertion that stops the run with a message (libFuzzer
// and the replay driver both report an abort as a failure, with the input that caused it), and a
// deterministic way to cut an input into chunks so the chunking is part of the fuzzed input.
#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#define FUZZ_CHECK(condition, what)                                                                        \
  do {                                                                                                     \
    if (!(condition)) {                                                                                    \
      std::fprintf(stderr, "fuzz check failed at %s:%d: %s (%s)\n", __FILE__, __LINE__, #condition, what); \
      std::abort();                                                                                        \
    }                                                                                                      \
  } while (0)

namespace ydscope::fuzz {

// Chunk sizes from one seed byte: 0 feeds byte by byte, 255 feeds everything at once, anything
// else draws sizes from 1 to seed (inclusive) with a small generator, so short and long splits
// (packets cut in their header, their samples, across several chunks) all get tried.
class Chunker {
 public:
  explicit Chunker(std::uint8_t seed) : seed_(seed), state_(seed * 0x9E3779B97F4A7C15ull + 1) {}

  std::size_t next(std::size_t remaining) {
    if (seed_ == 0) return remaining ? 1 : 0;
    if (seed_ == 255) return remaining;
    state_ ^= state_ << 13;
    state_ ^= state_ >> 7;
    state_ ^= state_ << 17;
    const std::size_t size = 1 + static_cast<std::size_t>(state_ % seed_);
    return size < remaining ? size : remaining;
  }

 private:
  std::uint8_t seed_;
  std::uint64_t state_;
};

// Calls f(chunk) for consecutive chunks of `bytes` as the chunker cuts them.
template <typename F>
void for_each_chunk(std::span<const std::uint8_t> bytes, Chunker chunker, F&& f) {
  std::size_t at = 0;
  while (at < bytes.size()) {
    const std::size_t n = chunker.next(bytes.size() - at);
    f(bytes.subspan(at, n));
    at += n;
  }
}

// An input read as text split at NUL bytes: a command line, one argument per piece.
inline std::vector<std::string> split_arguments(const std::uint8_t* data, std::size_t size) {
  std::vector<std::string> args;
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  std::size_t start = 0;
  while (start <= text.size()) {
    const std::size_t end = std::min(text.find('\0', start), text.size());
    args.emplace_back(text.substr(start, end - start));
    start = end + 1;
  }
  return args;
}

}  // namespace ydscope::fuzz
