#pragma once
// Helpers shared by the protocol tests: building scan streams with the real encoder, reading the
// captures, and decoding a whole byte string into laps.
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <initializer_list>
#include <iterator>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "core/protocol/g1_ct.h"
#include "core/protocol/lap.h"
#include "core/protocol/model_profile.h"
#include "core/protocol/scan_decoder.h"
#include "core/protocol/scan_packet.h"
#include "test_data.h"

namespace ydscope::test {

using Bytes = std::vector<std::uint8_t>;

inline Bytes packet(std::uint8_t ct, double fsa_deg, double lsa_deg, std::vector<std::uint16_t> samples) {
  Bytes out;
  append_scan_packet({ct, encode_raw_angle(fsa_deg), encode_raw_angle(lsa_deg), samples}, out);
  return out;
}

inline void append(Bytes& out, const Bytes& more) { out.insert(out.end(), more.begin(), more.end()); }

// A G6-style stream: `laps` + 1 zero packets, each followed by `per_lap` packets of `lsn` samples
// covering the turn; the trailing zero packet closes the last lap. Sample values vary per point.
inline Bytes synthetic_stream(int laps, int per_lap, int lsn, std::uint16_t base = 4000) {
  Bytes out;
  const double span = 360.0 / per_lap;
  std::uint16_t value = base;
  for (int lap = 0; lap <= laps; ++lap) {
    append(out, packet(kCtLapStart, 0.0, 0.0, {0}));
    if (lap == laps) break;
    for (int i = 0; i < per_lap; ++i) {
      std::vector<std::uint16_t> samples(static_cast<std::size_t>(lsn));
      for (auto& s : samples) s = value = static_cast<std::uint16_t>(value * 31 + 7);
      const double first = i * span + 0.2;
      append(out, packet(0, first, first + span - 0.4, samples));
    }
  }
  return out;
}

// G1 lap: zero packet preceded by `last_crc`, then packets whose CTs carry version and health.
struct G1LapSpec {
  double scan_hz = 9.0;
  std::uint8_t major = 1, minor = 5, health = 0;
  int packets = 6;  // after the zero packet
  int lsn = 10;
  std::uint16_t sample = (1000 << 2);
};

inline std::vector<std::uint8_t> g1_lap_cts(const G1LapSpec& spec) {
  std::vector<std::uint8_t> cts{g1_zero_packet_ct(spec.scan_hz)};
  for (int i = 1; i <= spec.packets; ++i) {
    std::uint8_t ct = static_cast<std::uint8_t>(0x20 + 2 * i);  // "production data"
    if (i == 1) ct = g1_version_ct(spec.major, spec.minor);
    if (i == 3) ct = g1_health_ct(spec.health);
    cts.push_back(ct);
  }
  return cts;
}

// Appends one G1 lap whose zero packet is preceded by `last_crc`; returns the CRC8 of its CTs.
inline std::uint8_t append_g1_lap(Bytes& out, const G1LapSpec& spec, std::uint8_t last_crc) {
  const auto cts = g1_lap_cts(spec);
  out.push_back(last_crc);
  append(out, packet(cts[0], 0.0, 0.0, {spec.sample}));
  const double span = 360.0 / spec.packets;
  for (int i = 1; i <= spec.packets; ++i) {
    const double first = (i - 1) * span + 1.0;
    append(out, packet(cts[static_cast<std::size_t>(i)], first, first + span - 2.0,
                       std::vector<std::uint16_t>(static_cast<std::size_t>(spec.lsn), spec.sample)));
  }
  return ct_crc8(cts);
}

inline Bytes read_file(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw std::runtime_error("cannot open " + path.string());
  return Bytes(std::istreambuf_iterator<char>(in), {});
}

inline std::filesystem::path capture(const std::string& name) { return captures_dir() / name; }

// The .hex captures: whitespace-separated hex bytes; lines starting with '#' are notes.
inline Bytes read_hex_capture(const std::filesystem::path& path) {
  std::ifstream in(path);
  if (!in) throw std::runtime_error("cannot open " + path.string());
  Bytes out;
  std::string line;
  while (std::getline(in, line)) {
    if (line.empty() || line[0] == '#') continue;
    std::istringstream words(line);
    std::string word;
    while (words >> word) out.push_back(static_cast<std::uint8_t>(std::stoul(word, nullptr, 16)));
  }
  return out;
}

struct Decoded {
  std::vector<Lap> laps;
  DecoderCounters counters;
};

// Feeds `bytes` in chunks of the given sizes (cycled; empty = all at once).
inline Decoded decode(const ModelProfile& profile, const Bytes& bytes, std::vector<std::size_t> chunks = {},
                      std::optional<double> scale = std::nullopt) {
  ScanDecoder decoder(profile, scale);
  Decoded result;
  std::size_t pos = 0;
  std::size_t next_chunk = 0;
  while (pos < bytes.size()) {
    std::size_t size = chunks.empty() ? bytes.size() : chunks[next_chunk++ % chunks.size()];
    size = std::min(size, bytes.size() - pos);
    decoder.feed({bytes.data() + pos, size}, static_cast<std::int64_t>(pos),
                 [&](const Lap& lap) { result.laps.push_back(lap); });
    pos += size;
  }
  decoder.finish([&](const Lap& lap) { result.laps.push_back(lap); });
  result.counters = decoder.counters();
  return result;
}

}  // namespace ydscope::test
