#pragma once
// StreamDiagnosis: when bytes arrive but no scan packet verifies, why, in one sentence a user can
// act on ("try --baud 230400", "this is a 3-byte-sample lidar"), instead of "no data" or a count of
// checksum errors. Fed the same raw chunks as PacketDecoder, it keeps only the last kWindowBytes;
// once kMinBytes have come it tries, on the same bytes, every AA 55 layout the YDLIDAR families
// use (2-byte samples: G1/G6/TG, X4, X2, G4...; 3-byte samples with intensity: T-mini Pro, G2,
// G4B), command replies (A5 5A), and nothing at all (the line runs at another baud).
//
// Pure protocol code like the decoder: no threads, no Boost, fixed memory. The session feeds it
// only until a packet verifies, so a healthy stream costs nothing.
#include <array>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <span>
#include <string>

#include "core/protocol/model_profile.h"

namespace ydscope {

// What the window holds, counted by trying every layout on the same bytes.
struct StreamFindings {
  std::size_t window_bytes = 0;
  std::size_t headers = 0;             // AA 55 pairs anywhere
  std::size_t two_byte_packets = 0;    // packets verifying as 2-byte samples (PacketDecoder)
  std::size_t two_byte_bytes = 0;      // their bytes
  std::size_t two_byte_samples = 0;    // their samples
  std::uint8_t two_byte_max_lsn = 0;   // largest LSN among them
  std::size_t three_byte_packets = 0;  // packets verifying as intensity byte + u16 distance
  std::size_t three_byte_bytes = 0;
  std::size_t three_byte_samples = 0;
  std::uint8_t three_byte_max_lsn = 0;
  std::size_t reply_bytes = 0;     // A5 5A replies: header and the payload its length names
  std::size_t top_byte_count = 0;  // how often the most frequent byte value occurs
  std::uint8_t top_byte = 0;
  std::optional<double> bytes_per_s;  // from the chunks' receive times, when they were given
};

class StreamDiagnosis {
 public:
  static constexpr std::size_t kWindowBytes = 8192;
  // Enough for several packets of any layout (the longest is 775 bytes): below it, no verdict.
  static constexpr std::size_t kMinBytes = 2048;

  // rx_ns: the chunk's receive time (any monotonic clock; 0 if unknown), for the sample rate.
  void feed(std::span<const std::uint8_t> bytes, std::int64_t rx_ns = 0);
  void reset();

  std::uint64_t bytes_seen() const { return bytes_seen_; }
  std::size_t window_size() const { return size_; }
  StreamFindings findings() const;
  // The sentence, or empty while fewer than kMinBytes have come or while the bytes fit `expected`
  // (its layout verifies and no hint says otherwise). baud: the line's rate, 0 when it has none
  // (TCP, replay).
  std::optional<std::string> verdict(const ModelProfile& expected, std::uint32_t baud) const;

 private:
  std::array<std::uint8_t, kWindowBytes> window_{};  // the last size_ bytes, oldest first
  std::size_t size_ = 0;
  std::uint64_t bytes_seen_ = 0;
  std::int64_t first_rx_ns_ = 0;         // receive time of the first timed chunk
  std::int64_t last_rx_ns_ = 0;          // and of the latest
  std::uint64_t bytes_after_first_ = 0;  // bytes that arrived after first_rx_ns_
};

}  // namespace ydscope
