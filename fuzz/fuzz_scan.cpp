// Fuzzes one model's scan decoder (PacketDecoder + LapAssembler) with arbitrary bytes.
// Input: byte 0 chooses how the rest is cut into chunks (fuzz_input.h), the rest is the stream.
// Beyond "no crash, no sanitizer report", it checks what the decoder promises:
// - chunking never changes the result: the same laps and counters as the stream fed whole;
// - byte accounting: bytes == packet_bytes + resync_bytes + last_crc_bytes + pending_bytes;
// - every lap point has an angle in [0, 360) and a finite range >= 0; no lap exceeds kMaxPoints;
// - laps are numbered 0, 1, 2, ... and the lap counter matches the laps delivered.
#include <cmath>
#include <cstdint>
#include <cstring>
#include <vector>

#include "core/protocol/model_profile.h"
#include "core/protocol/packet_decoder.h"
#include "core/protocol/scan_decoder.h"
#include "fuzz/fuzz_input.h"

namespace {

using namespace ydscope;

struct LapDigest {
  std::uint64_t index = 0;
  std::size_t points = 0;
  std::uint64_t hash = 1469598103934665603ull;  // FNV-1a over every point's bits and the CT fields
  bool operator==(const LapDigest&) const = default;
};

void mix(std::uint64_t& hash, const void* bytes, std::size_t n) {
  const auto* p = static_cast<const std::uint8_t*>(bytes);
  for (std::size_t i = 0; i < n; ++i) hash = (hash ^ p[i]) * 1099511628211ull;
}

LapDigest digest(const Lap& lap) {
  LapDigest d{lap.index, lap.points.size()};
  FUZZ_CHECK(lap.points.size() <= Lap::kMaxPoints, "lap grew past its preallocated capacity");
  for (const LapPoint& p : lap.points) {
    FUZZ_CHECK(std::isfinite(p.angle_deg) && p.angle_deg >= 0.0f && p.angle_deg < 360.0f, "angle outside [0, 360)");
    FUZZ_CHECK(std::isfinite(p.range_mm) && p.range_mm >= 0.0f, "range not a finite non-negative number");
    mix(d.hash, &p.angle_deg, sizeof p.angle_deg);
    mix(d.hash, &p.range_mm, sizeof p.range_mm);
    mix(d.hash, &p.flag, sizeof p.flag);
  }
  const double hz = lap.scan_hz.value_or(-1.0);
  const int health = lap.health_bits ? *lap.health_bits : -1;
  const int version = lap.version ? lap.version->major * 256 + lap.version->minor : -1;
  mix(d.hash, &hz, sizeof hz);
  mix(d.hash, &health, sizeof health);
  mix(d.hash, &version, sizeof version);
  mix(d.hash, &lap.crc, sizeof lap.crc);
  mix(d.hash, &lap.packets, sizeof lap.packets);
  mix(d.hash, &lap.checksum_errors, sizeof lap.checksum_errors);
  return d;
}

struct Decoded {
  std::vector<LapDigest> laps;
  DecoderCounters counters;
};

// Decoders are built once (each builds a 64 Ki-entry correction table and preallocates two laps)
// and reset per input, which also holds reset() to its promise of a fresh decoder.
ScanDecoder& fresh_decoder(const ModelProfile& profile, int which) {
  static ScanDecoder decoders[2] = {ScanDecoder(profile), ScanDecoder(profile)};
  decoders[which].reset();
  return decoders[which];
}

Decoded decode(const ModelProfile& profile, std::span<const std::uint8_t> stream, fuzz::Chunker chunker, int which) {
  ScanDecoder& decoder = fresh_decoder(profile, which);
  Decoded out;
  auto on_lap = [&](const Lap& lap) {
    FUZZ_CHECK(lap.index == out.laps.size(), "laps not numbered consecutively from 0");
    out.laps.push_back(digest(lap));
  };
  fuzz::for_each_chunk(stream, chunker, [&](std::span<const std::uint8_t> chunk) {
    decoder.feed(chunk, 0, on_lap);
    (void)decoder.lap_end_outlook();  // read between chunks, as the session does
  });
  decoder.finish(on_lap);
  out.counters = decoder.counters();
  FUZZ_CHECK(out.counters.laps == out.laps.size(), "lap counter disagrees with the laps delivered");
  FUZZ_CHECK(out.counters.bytes == stream.size(), "byte counter disagrees with the bytes fed");
  return out;
}

bool same_counters(const DecoderCounters& a, const DecoderCounters& b) {
  return std::memcmp(&a, &b, sizeof a) == 0;  // all std::uint64_t fields, no padding
}

class CountingSink final : public PacketSink {
 public:
  void on_packet(const PacketView& packet) override {
    FUZZ_CHECK(packet.lsn >= 1, "a packet without samples was emitted");
    ++packets;
  }
  void on_checksum_error() override { ++checksum_errors; }
  std::uint64_t packets = 0;
  std::uint64_t checksum_errors = 0;
};

void check_byte_accounting(const ModelProfile& profile, std::span<const std::uint8_t> stream, fuzz::Chunker chunker) {
  PacketDecoder decoder(profile.last_crc_before_zero);
  CountingSink sink;
  auto balanced = [&] {
    const PacketCounters& c = decoder.counters();
    return c.bytes == c.packet_bytes + c.resync_bytes + c.last_crc_bytes + c.pending_bytes &&
           c.pending_bytes == decoder.partial_packet().size();
  };
  fuzz::for_each_chunk(stream, chunker, [&](std::span<const std::uint8_t> chunk) {
    decoder.feed(chunk, 0, sink);
    FUZZ_CHECK(balanced(), "byte accounting does not add up after a chunk");
  });
  decoder.finish(sink);
  FUZZ_CHECK(balanced(), "byte accounting does not add up after finish");
  FUZZ_CHECK(decoder.counters().packets == sink.packets, "packet counter disagrees with the packets emitted");
  FUZZ_CHECK(decoder.counters().checksum_errors == sink.checksum_errors, "checksum counter disagrees with the sink");
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size < 1) return 0;
  const ModelProfile& profile = profile_for(Model::YDSCOPE_FUZZ_MODEL);
  const fuzz::Chunker chunker(data[0]);
  const std::span<const std::uint8_t> stream(data + 1, size - 1);

  const Decoded whole = decode(profile, stream, fuzz::Chunker(255), 0);
  const Decoded chunked = decode(profile, stream, chunker, 1);
  FUZZ_CHECK(same_counters(whole.counters, chunked.counters), "chunking changed the decoder's counters");
  FUZZ_CHECK(whole.laps == chunked.laps, "chunking changed the laps decoded");
  check_byte_accounting(profile, stream, chunker);
  return 0;
}
