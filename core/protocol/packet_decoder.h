#pragma once
// PacketDecoder: the streaming scan-packet framer. Fed arbitrary chunks (one byte to megabytes),
// it hunts `AA 55`, checks the FSA/LSA check bits, LSN >= 1 (every real packet has a sample; a
// stray AA 55 with LSN 0 is treated as a failed start) and the XOR checksum, and hands every valid
// packet to a sink. After a failed header or checksum it resyncs one byte after the failed start,
// so `AA AA 55 ...` is found at the second AA and a packet hidden inside damaged bytes is not lost.
//
// Packets that lie whole inside a chunk are checked in place; only a packet split across chunks
// is copied, into a fixed buffer of kMaxPacketSize bytes. Nothing allocates after construction.
// A packet cut off at the end of the stream is never emitted; its bytes show as pending_bytes.
//
// Byte accounting: bytes == packet_bytes + resync_bytes + last_crc_bytes + pending_bytes.
#include <array>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <span>

#include "core/protocol/scan_packet.h"

namespace ydscope {

// One valid packet. Views into decoder or caller memory: valid only during the sink call.
struct PacketView {
  std::uint8_t ct = 0;
  std::uint8_t lsn = 0;
  std::uint16_t fsa = 0;
  std::uint16_t lsa = 0;
  const std::uint8_t* sample_bytes = nullptr;  // 2*lsn bytes, little-endian u16 each
  // G1: the LastCRC byte that preceded this zero packet; empty when none did (or not G1). When
  // several bytes lie between the previous packet and the zero packet, the last one (right
  // before the AA 55) is taken: the device sends LastCRC immediately before the zero packet,
  // so earlier bytes are junk.
  std::optional<std::uint8_t> last_crc;
  std::int64_t first_rx_ns = 0;  // receive time of the chunk holding the packet's first byte
  std::int64_t rx_ns = 0;        // receive time of the chunk that completed it

  bool lap_start() const { return is_lap_start(ct); }
  std::uint16_t sample(std::size_t i) const {
    return static_cast<std::uint16_t>(sample_bytes[2 * i] | (sample_bytes[2 * i + 1] << 8));
  }
};

class PacketSink {
 public:
  virtual ~PacketSink() = default;
  virtual void on_packet(const PacketView& packet) = 0;
  // A packet whose header looked valid but whose checksum did not match (it was dropped).
  virtual void on_checksum_error() = 0;
};

struct PacketCounters {
  std::uint64_t bytes = 0;            // every byte fed
  std::uint64_t packets = 0;          // packets with a valid checksum
  std::uint64_t zero_packets = 0;     // of which CT bit 0 was set
  std::uint64_t packet_bytes = 0;     // bytes of those packets
  std::uint64_t checksum_errors = 0;  // well-formed headers whose checksum did not match
  std::uint64_t resync_bytes = 0;     // bytes skipped while hunting: junk, reply headers, failed starts
  std::uint64_t last_crc_bytes = 0;   // bytes taken in front of zero packets (G1's LastCRC, TG's byte)
  std::uint64_t pending_bytes = 0;    // bytes held for a packet that is not complete yet
};

class PacketDecoder {
 public:
  // last_crc_before_zero: one byte precedes each zero packet (G1's LastCRC; a real TG's byte, see
  // unit_conventions.h).
  explicit PacketDecoder(bool last_crc_before_zero = false);

  // Consumes all of `bytes`; calls the sink for every packet completed or found bad.
  // rx_ns is the receive time of this chunk (any monotonic clock; 0 if unknown).
  void feed(std::span<const std::uint8_t> bytes, std::int64_t rx_ns, PacketSink& sink);

  // The stream has ended: a held candidate can never complete. If valid packets hide behind it
  // (a false AA 55 inside damaged bytes claimed a long packet), they are emitted now. A real
  // cut-off packet stays counted in pending_bytes.
  void finish(PacketSink& sink);

  const PacketCounters& counters() const { return counters_; }
  // G1: the last byte skipped may be the LastCRC of a zero packet still to come (counted as a
  // resync byte until that packet makes it a LastCRC byte).
  bool may_hold_last_crc() const { return last_crc_before_zero_ && junk_run_ > 0; }
  // The bytes held of a packet not complete yet (they start at its AA); empty at a boundary.
  std::span<const std::uint8_t> partial_packet() const { return {pending_.data(), pending_size_}; }
  // Forget buffered bytes and counters (e.g. after a reconnect).
  void reset();

 private:
  enum class Check { NeedMore, Packet, Bad, BadChecksum };
  Check check(const std::uint8_t* p, std::size_t available, std::size_t& size) const;
  void emit(const std::uint8_t* p, std::int64_t first_rx_ns, std::int64_t rx_ns, PacketSink& sink);
  void skip(const std::uint8_t* p, std::size_t count);
  void drain_buffer(std::span<const std::uint8_t>& bytes, std::int64_t rx_ns, PacketSink& sink);
  // Removes `count` already-accounted bytes from the front of pending_, then skips to the next AA.
  void drop_pending(std::size_t count);
  // Handles a decided candidate at the front of pending_; false when it needs more bytes.
  bool settle_pending(std::int64_t rx_ns, PacketSink& sink);

  bool last_crc_before_zero_;
  PacketCounters counters_;
  // Bytes of a packet started in an earlier chunk (always begins with 0xAA while non-empty).
  std::array<std::uint8_t, kMaxPacketSize> pending_{};
  std::size_t pending_size_ = 0;
  std::int64_t pending_rx_ns_ = 0;
  // The byte just before the current hunt position and how many junk bytes ran up to it, for G1's
  // LastCRC byte (it looks like one junk byte in front of a zero packet).
  std::uint8_t last_skipped_ = 0;
  std::size_t junk_run_ = 0;
};

}  // namespace ydscope
