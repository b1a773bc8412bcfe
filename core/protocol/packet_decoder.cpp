#include "core/protocol/packet_decoder.h"

#include <algorithm>
#include <bit>
#include <cstring>

#include "core/protocol/byte_access.h"

namespace ydscope {

namespace {

// XOR of the little-endian u16 words of `bytes` (an even count). Eight bytes at a time: the XOR of
// 64-bit words folds into the XOR of their four u16 lanes on a little-endian host.
std::uint16_t xor_words(const std::uint8_t* bytes, std::size_t size) {
  std::size_t i = 0;
  std::uint16_t folded = 0;
  if constexpr (std::endian::native == std::endian::little) {
    std::uint64_t wide = 0;
    for (; i + 8 <= size; i += 8) {
      std::uint64_t word;
      std::memcpy(&word, bytes + i, sizeof word);
      wide ^= word;
    }
    wide ^= wide >> 32;
    wide ^= wide >> 16;
    folded = static_cast<std::uint16_t>(wide);
  }
  for (; i + 1 < size; i += 2) folded ^= read_u16_le(bytes + i);
  return folded;
}

// How many bytes a candidate starting with AA needs before check() can decide.
std::size_t bytes_to_decide(const std::uint8_t* p, std::size_t available) {
  if (available < 2) return 2;
  if (available < kPacketHeaderSize) return kPacketHeaderSize;
  return packet_size(p[3]);
}

}  // namespace

PacketDecoder::PacketDecoder(bool last_crc_before_zero) : last_crc_before_zero_(last_crc_before_zero) {}

void PacketDecoder::reset() {
  counters_ = {};
  pending_size_ = 0;
  pending_rx_ns_ = 0;
  last_skipped_ = 0;
  junk_run_ = 0;
}

PacketDecoder::Check PacketDecoder::check(const std::uint8_t* p, std::size_t available, std::size_t& size) const {
  if (available < 2) return Check::NeedMore;
  if (p[1] != kPacketHeader1) return Check::Bad;
  if (available < kPacketHeaderSize) return Check::NeedMore;
  const std::uint8_t lsn = p[3];
  const std::uint16_t fsa = read_u16_le(p + 4);
  const std::uint16_t lsa = read_u16_le(p + 6);
  // Every real packet has at least one sample and both angle check bits set; rejecting anything
  // else here keeps a stray AA 55 inside samples from making us wait for a long fake packet.
  if (lsn == 0 || !angle_check_bit_ok(fsa) || !angle_check_bit_ok(lsa)) return Check::Bad;
  size = packet_size(lsn);
  if (available < size) return Check::NeedMore;
  const std::uint16_t expected = read_u16_le(p + 8);
  const std::uint16_t header_words = static_cast<std::uint16_t>(kPacketHeaderWord ^ (p[2] | (lsn << 8)) ^ fsa ^ lsa);
  const std::uint16_t actual = header_words ^ xor_words(p + kPacketHeaderSize, size - kPacketHeaderSize);
  return actual == expected ? Check::Packet : Check::BadChecksum;
}

void PacketDecoder::skip(const std::uint8_t* p, std::size_t count) {
  if (count == 0) return;
  counters_.resync_bytes += count;
  junk_run_ += count;
  last_skipped_ = p[count - 1];
}

void PacketDecoder::emit(const std::uint8_t* p, std::int64_t first_rx_ns, std::int64_t rx_ns, PacketSink& sink) {
  PacketView packet;
  packet.ct = p[2];
  packet.lsn = p[3];
  packet.fsa = read_u16_le(p + 4);
  packet.lsa = read_u16_le(p + 6);
  packet.sample_bytes = p + kPacketHeaderSize;
  packet.first_rx_ns = first_rx_ns;
  packet.rx_ns = rx_ns;
  const bool zero = packet.lap_start();
  // G1's LastCRC byte arrives as one byte outside any packet, right before the zero packet.
  if (zero && last_crc_before_zero_ && junk_run_ > 0) {
    packet.last_crc = last_skipped_;
    --counters_.resync_bytes;
    ++counters_.last_crc_bytes;
  }
  junk_run_ = 0;
  ++counters_.packets;
  if (zero) ++counters_.zero_packets;
  counters_.packet_bytes += packet_size(packet.lsn);
  sink.on_packet(packet);
}

void PacketDecoder::drop_pending(std::size_t count) {
  const auto* rest = pending_.data() + count;
  const std::size_t rest_size = pending_size_ - count;
  const auto* next = static_cast<const std::uint8_t*>(std::memchr(rest, kPacketHeader0, rest_size));
  const std::size_t junk = next ? static_cast<std::size_t>(next - rest) : rest_size;
  skip(rest, junk);
  pending_size_ = rest_size - junk;
  if (pending_size_ > 0) std::memmove(pending_.data(), rest + junk, pending_size_);
}

bool PacketDecoder::settle_pending(std::int64_t rx_ns, PacketSink& sink) {
  std::size_t size = 0;
  switch (check(pending_.data(), pending_size_, size)) {
    case Check::NeedMore: return false;
    case Check::Packet:
      emit(pending_.data(), pending_rx_ns_, rx_ns, sink);
      drop_pending(size);
      return true;
    case Check::BadChecksum:
      ++counters_.checksum_errors;
      sink.on_checksum_error();
      [[fallthrough]];
    case Check::Bad:
      skip(pending_.data(), 1);
      drop_pending(1);
      return true;
  }
  return true;
}

// Works off the bytes held from earlier chunks, topping them up from `bytes` only as far as a
// decision needs, so the rest of the chunk can still be checked in place.
void PacketDecoder::drain_buffer(std::span<const std::uint8_t>& bytes, std::int64_t rx_ns, PacketSink& sink) {
  while (pending_size_ > 0) {
    if (settle_pending(rx_ns, sink)) continue;
    const std::size_t need = bytes_to_decide(pending_.data(), pending_size_);
    const std::size_t take = std::min(need - pending_size_, bytes.size());
    if (take == 0) return;
    std::memcpy(pending_.data() + pending_size_, bytes.data(), take);
    pending_size_ += take;
    bytes = bytes.subspan(take);
  }
}

void PacketDecoder::finish(PacketSink& sink) {
  while (pending_size_ > 0) {
    if (settle_pending(pending_rx_ns_, sink)) continue;
    // The front candidate is incomplete for good. Resync past it only if a whole valid packet
    // follows inside the held bytes; otherwise the bytes are a real cut-off packet.
    std::size_t later = 0;
    for (std::size_t at = 1; at < pending_size_ && later == 0; ++at) {
      std::size_t size = 0;
      if (pending_[at] == kPacketHeader0 && check(pending_.data() + at, pending_size_ - at, size) == Check::Packet)
        later = at;
    }
    if (later == 0) break;
    skip(pending_.data(), later);
    drop_pending(later);
  }
  counters_.pending_bytes = pending_size_;
}

void PacketDecoder::feed(std::span<const std::uint8_t> bytes, std::int64_t rx_ns, PacketSink& sink) {
  counters_.bytes += bytes.size();
  if (pending_size_ > 0) drain_buffer(bytes, rx_ns, sink);

  const std::uint8_t* p = bytes.data();
  const std::uint8_t* const end = p + bytes.size();
  while (p < end) {
    if (*p != kPacketHeader0) {
      const auto* next =
          static_cast<const std::uint8_t*>(std::memchr(p, kPacketHeader0, static_cast<std::size_t>(end - p)));
      if (!next) next = end;
      skip(p, static_cast<std::size_t>(next - p));
      p = next;
      continue;
    }
    std::size_t size = 0;
    switch (check(p, static_cast<std::size_t>(end - p), size)) {
      case Check::Packet:
        emit(p, rx_ns, rx_ns, sink);
        p += size;
        break;
      case Check::NeedMore:
        pending_size_ = static_cast<std::size_t>(end - p);  // < kMaxPacketSize: it needs more
        std::memcpy(pending_.data(), p, pending_size_);
        pending_rx_ns_ = rx_ns;
        p = end;
        break;
      case Check::BadChecksum:
        ++counters_.checksum_errors;
        sink.on_checksum_error();
        [[fallthrough]];
      case Check::Bad:
        skip(p, 1);
        ++p;
        break;
    }
  }
  counters_.pending_bytes = pending_size_;
}

}  // namespace ydscope
