// Decode throughput (bytes/s) on a synthetic G6 stream, and the generator of the 64 MiB stream
// used to compare `ydscope-cli decode --format summary` with md5sum:
//
//   bench_decode --generate FILE [MIB]   writes MIB (default 64) MiB of G6 scan stream to FILE
//   bench_decode [benchmark flags]       runs the Google Benchmark cases
//
// The stream is what a G6 at 9 kHz ranging and 10 Hz sends: a zero packet, then packets of 40
// samples covering the turn (900 points per lap), with distances that vary from point to point.
#include <benchmark/benchmark.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>
#include <vector>

#include "core/protocol/model_profile.h"
#include "core/protocol/packet_decoder.h"
#include "core/protocol/scan_decoder.h"
#include "core/protocol/unit_conventions.h"
#include "core/protocol/scan_packet.h"

namespace {

using namespace ydscope;

constexpr int kSamplesPerPacket = 40;
constexpr int kPacketsPerLap = 23;  // 22.5 in reality; the last one overlaps a little

// One lap: zero packet + kPacketsPerLap packets; `seed` varies the scene between laps.
void append_lap(std::vector<std::uint8_t>& out, unsigned seed) {
  const ModelProfile& g6 = profile_for(Model::G6);
  const double scale = conventions_for(g6, std::nullopt, Reading::Manual).distance_scale;
  const std::uint16_t zero_sample[] = {encode_sample(1500.0, PointFlag::None, g6.flag_bits, scale)};
  append_scan_packet({kCtLapStart, encode_raw_angle(0.0), encode_raw_angle(0.0), zero_sample}, out);
  const double span = 360.0 / kPacketsPerLap;
  std::vector<std::uint16_t> samples(kSamplesPerPacket);
  for (int p = 0; p < kPacketsPerLap; ++p) {
    for (int i = 0; i < kSamplesPerPacket; ++i) {
      const double angle = (p * kSamplesPerPacket + i) * 0.4;
      // A room: walls 1-8 m away, some points without a return.
      const double range = 1000.0 + 7000.0 * std::fabs(std::sin((angle + seed * 7.0) * 0.017)) +
                           ((seed * 131u + static_cast<unsigned>(i) * 17u) % 50u);
      const bool no_return = ((static_cast<unsigned>(p * kSamplesPerPacket + i) + seed) % 37u) == 0;
      samples[static_cast<std::size_t>(i)] = no_return ? 0 : encode_sample(range, PointFlag::None, g6.flag_bits, scale);
    }
    const double first = p * span + 0.1;
    append_scan_packet({0x00, encode_raw_angle(first), encode_raw_angle(first + span - 0.3), samples}, out);
  }
}

std::vector<std::uint8_t> make_stream(std::size_t bytes) {
  std::vector<std::uint8_t> out{0xA5, 0x5A, 0x05, 0x00, 0x00, 0x40, 0x81};  // the scan reply header
  out.reserve(bytes + 4096);
  for (unsigned lap = 0; out.size() < bytes; ++lap) append_lap(out, lap % 64);
  out.resize(bytes);  // the stream is cut wherever the capture stopped, like a real one
  return out;
}

const std::vector<std::uint8_t>& stream() {
  static const std::vector<std::uint8_t> bytes = make_stream(8u << 20);
  return bytes;
}

void BM_ScanDecoderG6(benchmark::State& state) {
  const auto& bytes = stream();
  const auto chunk = static_cast<std::size_t>(state.range(0));
  std::uint64_t points = 0;
  for (auto _ : state) {
    ScanDecoder decoder(profile_for(Model::G6));
    for (std::size_t pos = 0; pos < bytes.size(); pos += chunk) {
      const std::size_t size = std::min(chunk, bytes.size() - pos);
      decoder.feed({bytes.data() + pos, size}, 0, [&](const Lap& lap) { points += lap.points.size(); });
    }
    benchmark::DoNotOptimize(points);
  }
  state.SetBytesProcessed(static_cast<std::int64_t>(state.iterations() * bytes.size()));
  state.counters["points/s"] = benchmark::Counter(static_cast<double>(points), benchmark::Counter::kIsRate);
}
// 512 B ~ a serial read at 512000 baud; 1 MiB ~ the CLI's file reads.
BENCHMARK(BM_ScanDecoderG6)->Arg(512)->Arg(1 << 20)->Unit(benchmark::kMillisecond);

struct CountingSink final : PacketSink {
  std::uint64_t samples = 0;
  void on_packet(const PacketView& packet) override { samples += packet.lsn; }
  void on_checksum_error() override {}
};

// Framing and checksums alone, to see what the lap assembly (angles, ranges) costs on top.
void BM_PacketFramingOnly(benchmark::State& state) {
  const auto& bytes = stream();
  CountingSink sink;
  for (auto _ : state) {
    PacketDecoder decoder;
    decoder.feed(bytes, 0, sink);
    benchmark::DoNotOptimize(sink.samples);
  }
  state.SetBytesProcessed(static_cast<std::int64_t>(state.iterations() * bytes.size()));
}
BENCHMARK(BM_PacketFramingOnly)->Unit(benchmark::kMillisecond);

int generate(const char* path, const char* mib_text) {
  const long mib = mib_text ? std::strtol(mib_text, nullptr, 10) : 64;
  if (mib <= 0 || mib > 4096) {
    std::fprintf(stderr, "bench_decode --generate: MIB must be 1..4096, not '%s'\n", mib_text);
    return 2;
  }
  const auto bytes = make_stream(static_cast<std::size_t>(mib) << 20);
  std::FILE* file = std::fopen(path, "wb");
  if (!file || std::fwrite(bytes.data(), 1, bytes.size(), file) != bytes.size() || std::fclose(file) != 0) {
    std::fprintf(stderr, "bench_decode --generate: cannot write '%s': %s\n", path, std::strerror(errno));
    return 1;
  }
  std::printf("wrote %zu bytes of G6 scan stream to %s\n", bytes.size(), path);
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc >= 3 && std::strcmp(argv[1], "--generate") == 0) return generate(argv[2], argc >= 4 ? argv[3] : nullptr);
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
