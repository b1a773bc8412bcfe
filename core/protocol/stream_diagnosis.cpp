#include "core/protocol/stream_diagnosis.h"

#include <algorithm>
#include <cstdio>
#include <cstring>
#include <string_view>
#include <vector>

#include "core/protocol/byte_access.h"
#include "core/protocol/packet_decoder.h"
#include "core/protocol/scan_packet.h"

namespace ydscope {

namespace {

enum class Layout : std::uint8_t { TwoByte, ThreeByte };

struct KnownFamily {
  std::string_view name;
  std::string_view codes;  // device-info model code(s), as the table gives them
  std::uint8_t code_min, code_max;
  std::uint32_t baud;
  double min_ksps, max_ksps;  // samples per second a host receives, in thousands
  Layout layout;
  std::string_view intensity;  // "" when the samples carry none
};

// The AA 55 families people own. Source: YDLidar-SDK doc/Dataset.md (model code, baud, sample
// rate, intensity bits); the T-mini Pro is not in that table: its code is the SDK's model enum
// (YDLIDAR_TminiPro = 150), its baud and 4 k rate its datasheet's. 8- and 10-bit intensity units
// send 3-byte samples (the SDK's NODE_QUAL8 / QUAL10: intensity byte, then the u16 distance word).
constexpr KnownFamily kFamilies[] = {
    {"G1", "19", 19, 19, 230400, 9, 9, Layout::TwoByte, ""},
    {"G6", "13", 13, 13, 512000, 8, 18, Layout::TwoByte, ""},
    {"TG15/TG30/TG50", "100-102", 100, 102, 512000, 10, 20, Layout::TwoByte, ""},
    {"X4", "6", 6, 6, 128000, 5, 5, Layout::TwoByte, ""},
    {"X2", "6", 6, 6, 115200, 3, 3, Layout::TwoByte, ""},
    {"S2", "4/12", 12, 12, 115200, 3, 3, Layout::TwoByte, ""},
    {"G4", "5", 5, 5, 230400, 4, 9, Layout::TwoByte, ""},
    {"G2C", "16", 16, 16, 115200, 4, 4, Layout::TwoByte, ""},
    {"T-mini Pro", "150", 150, 150, 230400, 4, 4, Layout::ThreeByte, "8-bit"},
    {"G2", "15", 15, 15, 230400, 5, 5, Layout::ThreeByte, "8-bit"},
    {"G4B", "17", 17, 17, 512000, 10, 10, Layout::ThreeByte, "10-bit"},
};

// The bauds these families run at, in the order the session probes them (kProbeBauds).
constexpr std::uint32_t kKnownBauds[] = {230400, 512000, 128000, 115200};

// A measured rate fits a family's within this fraction: the host's clock, bursts, a lap's gaps.
constexpr double kRateSlack = 0.3;
// A layout counts as found with this many verified packets (one could be chance in 8 KiB).
constexpr std::size_t kMinPackets = 3;

const KnownFamily* known_family_of(const ModelProfile& profile) {
  for (const KnownFamily& f : kFamilies)
    if (profile.model_code >= f.code_min && profile.model_code <= f.code_max && profile.default_baud == f.baud)
      return &f;
  return nullptr;
}

bool rate_fits(const KnownFamily& f, double ksps) {
  return ksps >= f.min_ksps * (1 - kRateSlack) && ksps <= f.max_ksps * (1 + kRateSlack);
}

std::string format(const char* fmt, double value) {
  char text[32];
  std::snprintf(text, sizeof text, fmt, value);
  return text;
}

std::string ksps_text(const KnownFamily& f) {
  return f.min_ksps == f.max_ksps ? format("%g k", f.min_ksps)
                                  : format("%g", f.min_ksps) + "-" + format("%g k", f.max_ksps);
}

std::string describe(const KnownFamily& f) {
  std::string text = std::string(f.name) + " (model code " + std::string(f.codes) + ", " + std::to_string(f.baud) +
                     " baud, " + ksps_text(f) + " samples/s";
  if (!f.intensity.empty()) text += ", " + std::string(f.intensity) + " intensity";
  return text + ")";
}

// "A", "A or B", "A, B or C".
std::string join_or(const std::vector<std::string>& items) {
  std::string text;
  for (std::size_t i = 0; i < items.size(); ++i) {
    if (i > 0) text += i + 1 == items.size() ? " or " : ", ";
    text += items[i];
  }
  return text;
}

// Families of `layout` other than `expected`, narrowed by the measured rate (when known) and then
// to those at the line's baud when any is.
std::vector<const KnownFamily*> candidates(Layout layout, const KnownFamily* expected, std::optional<double> ksps,
                                           std::uint32_t baud) {
  std::vector<const KnownFamily*> found;
  for (const KnownFamily& f : kFamilies)
    if (f.layout == layout && &f != expected && (!ksps || rate_fits(f, *ksps))) found.push_back(&f);
  std::vector<const KnownFamily*> at_baud;
  for (const KnownFamily* f : found)
    if (f->baud == baud) at_baud.push_back(f);
  return at_baud.empty() ? found : at_baud;
}

std::string family_list(const std::vector<const KnownFamily*>& families) {
  std::vector<std::string> names;
  names.reserve(families.size());
  for (const KnownFamily* f : families) names.push_back(describe(*f));
  return join_or(names);
}

// Bauds worth trying: the expected model's own first, then the other known ones.
std::string baud_advice(const ModelProfile& expected, std::uint32_t baud) {
  std::vector<std::string> bauds;
  auto add = [&](std::uint32_t b) {
    const std::string text = std::to_string(b);
    if (b != baud && std::find(bauds.begin(), bauds.end(), text) == bauds.end()) bauds.push_back(text);
  };
  add(expected.default_baud);
  for (const std::uint32_t b : kKnownBauds) add(b);
  return "try --baud auto, or --baud " + join_or(bauds);
}

// Samples per second, in thousands, of `samples` in the window at the measured byte rate.
std::optional<double> samples_ksps(const StreamFindings& f, std::size_t samples) {
  if (!f.bytes_per_s || f.window_bytes == 0) return std::nullopt;
  return f.bytes_per_s.value() * static_cast<double>(samples) / static_cast<double>(f.window_bytes) / 1000;
}

std::string at_baud(std::uint32_t baud) { return baud ? " at " + std::to_string(baud) + " baud" : ""; }

std::string models_decoded() { return "ydscope decodes " + std::string(model_names()) + " only"; }

// The 2-byte layout, counted by the decoder itself so "verifies" means what the session means.
struct TwoByteCount final : PacketSink {
  StreamFindings& f;
  explicit TwoByteCount(StreamFindings& findings) : f(findings) {}
  void on_packet(const PacketView& packet) override {
    ++f.two_byte_packets;
    f.two_byte_bytes += packet_size(packet.lsn);
    f.two_byte_samples += packet.lsn;
    f.two_byte_max_lsn = std::max(f.two_byte_max_lsn, packet.lsn);
  }
  void on_checksum_error() override {}
};

// Size of the 3-byte-sample packet at p (intensity byte, then u16 distance, per sample) when its
// checksum verifies, else 0. The checksum XORs the header words as the 2-byte layout does, then per
// sample the intensity byte as a u16 with high byte 0 and the distance word (vendor SDK
// calcCheckSum; tier4/ydlidar_driver checksum.rs).
std::size_t three_byte_packet(const std::uint8_t* p, std::size_t available) {
  if (available < kPacketHeaderSize || p[0] != kPacketHeader0 || p[1] != kPacketHeader1) return 0;
  const std::uint8_t lsn = p[3];
  const std::uint16_t fsa = read_u16_le(p + 4);
  const std::uint16_t lsa = read_u16_le(p + 6);
  if (lsn == 0 || !angle_check_bit_ok(fsa) || !angle_check_bit_ok(lsa)) return 0;
  const std::size_t size = kPacketHeaderSize + std::size_t{3} * lsn;
  if (available < size) return 0;
  std::uint16_t cs = packet_checksum(p[2], lsn, fsa, lsa, {});
  for (const std::uint8_t* s = p + kPacketHeaderSize; s < p + size; s += 3)
    cs = static_cast<std::uint16_t>(cs ^ s[0] ^ read_u16_le(s + 1));
  return cs == read_u16_le(p + 8) ? size : 0;
}

}  // namespace

void StreamDiagnosis::reset() {
  size_ = 0;
  bytes_seen_ = 0;
  first_rx_ns_ = last_rx_ns_ = 0;
  bytes_after_first_ = 0;
}

void StreamDiagnosis::feed(std::span<const std::uint8_t> bytes, std::int64_t rx_ns) {
  bytes_seen_ += bytes.size();
  if (rx_ns != 0 && !bytes.empty()) {
    if (first_rx_ns_ == 0)
      first_rx_ns_ = rx_ns;  // this chunk's bytes came before it: not counted
    else
      bytes_after_first_ += bytes.size();
    last_rx_ns_ = rx_ns;
  }
  if (bytes.size() >= kWindowBytes) bytes = bytes.last(kWindowBytes);
  const std::size_t overflow = size_ + bytes.size() > kWindowBytes ? size_ + bytes.size() - kWindowBytes : 0;
  if (overflow > 0) {
    std::memmove(window_.data(), window_.data() + overflow, size_ - overflow);
    size_ -= overflow;
  }
  if (!bytes.empty()) std::memcpy(window_.data() + size_, bytes.data(), bytes.size());
  size_ += bytes.size();
}

StreamFindings StreamDiagnosis::findings() const {
  StreamFindings f;
  f.window_bytes = size_;
  const std::uint8_t* const p = window_.data();
  if (last_rx_ns_ > first_rx_ns_ && bytes_after_first_ > 0)
    f.bytes_per_s = static_cast<double>(bytes_after_first_) * 1e9 / static_cast<double>(last_rx_ns_ - first_rx_ns_);

  PacketDecoder decoder;
  TwoByteCount two(f);
  decoder.feed({p, size_}, 0, two);
  decoder.finish(two);

  std::array<std::size_t, 256> histogram{};
  for (std::size_t i = 0; i < size_; ++i) {
    ++histogram[p[i]];
    if (i + 1 < size_ && p[i] == kPacketHeader0 && p[i + 1] == kPacketHeader1) ++f.headers;
  }
  const auto top = std::max_element(histogram.begin(), histogram.end());
  f.top_byte = static_cast<std::uint8_t>(top - histogram.begin());
  f.top_byte_count = *top;

  for (std::size_t i = 0; i + 1 < size_;) {
    if (const std::size_t size = three_byte_packet(p + i, size_ - i)) {
      ++f.three_byte_packets;
      f.three_byte_bytes += size;
      f.three_byte_samples += p[i + 3];
      f.three_byte_max_lsn = std::max(f.three_byte_max_lsn, p[i + 3]);
      i += size;
      continue;
    }
    // A reply: A5 5A, a u32 whose low 30 bits are the length and top 2 bits the mode, the type.
    if (p[i] == 0xA5 && p[i + 1] == 0x5A && i + 7 <= size_) {
      const std::uint32_t field = read_u32_le(p + i + 2);
      const std::uint32_t length = field & 0x3FFFFFFFu;
      // A single reply carries its payload; a continuous one (the scan's) is followed by packets.
      const bool single = (field >> 30) == 0 && length <= 64;
      const std::size_t size = std::min<std::size_t>(7 + (single ? length : 0), size_ - i);
      f.reply_bytes += size;
      i += size;
      continue;
    }
    ++i;
  }
  return f;
}

std::optional<std::string> StreamDiagnosis::verdict(const ModelProfile& expected, std::uint32_t baud) const {
  if (bytes_seen_ < kMinBytes) return std::nullopt;
  const StreamFindings f = findings();
  const std::string model(expected.name);
  const KnownFamily* own = known_family_of(expected);

  if (f.three_byte_packets >= kMinPackets && f.three_byte_bytes > f.two_byte_bytes) {
    const std::optional<double> ksps = samples_ksps(f, f.three_byte_samples);
    auto like = candidates(Layout::ThreeByte, own, ksps, baud);
    if (like.empty()) like = candidates(Layout::ThreeByte, own, std::nullopt, baud);
    return "these packets verify as 3-byte samples with intensity (LSN up to " + std::to_string(f.three_byte_max_lsn) +
           "), the layout of the " + family_list(like) + ", which the " + model + " does not use: this is not a " +
           model + ", and " + models_decoded() + ", so read this lidar with its vendor's SDK";
  }

  if (f.two_byte_packets >= kMinPackets) {
    const std::optional<double> ksps = samples_ksps(f, f.two_byte_samples);
    // A unit's baud is fixed, so bytes that verify at another model's baud are another model.
    const bool baud_fits = baud == 0 || baud == expected.default_baud;
    const bool rate_known_and_off = ksps && own && !rate_fits(*own, *ksps);
    if (baud_fits && !rate_known_and_off) return std::nullopt;
    const auto like = candidates(Layout::TwoByte, own, ksps, baud);
    std::string seen = "LSN up to " + std::to_string(f.two_byte_max_lsn);
    if (ksps) seen += format(", about %.1f k samples/s", *ksps);
    std::string text = "these packets verify as 2-byte samples (" + seen + ")" + at_baud(baud);
    text +=
        like.empty() ? ", the layout of a YDLIDAR unit other than the " + model : ", matching the " + family_list(like);
    text += ", not a " + model;
    if (own) text += " (" + ksps_text(*own) + " samples/s at " + std::to_string(own->baud) + " baud)";
    text += ": " + models_decoded();
    return text + (expected.model == Model::G6
                       ? ", and reads these with the G6's scale, not this lidar's"
                       : "; to draw them anyway, try --model G6, whose 2-byte layout they share");
  }

  const std::string arrive = "bytes arrive but no valid packets" + at_baud(baud);
  if (f.reply_bytes * 2 >= f.window_bytes)
    return arrive +
           ": only command replies (A5 5A) come, no scan packets, so the lidar answers but does not "
           "stream; check that its motor turns, then reconnect to start the scan again";
  // A real stream at the right baud has an AA 55 every packet (tens to hundreds of bytes); at a
  // wrong baud one turns up by chance about once in 64 KiB.
  if (f.headers * 512 >= f.window_bytes)
    return arrive + ": " + std::to_string(f.headers) + " AA 55 packet headers in the last " +
           std::to_string(f.window_bytes) +
           " bytes, but none verifies as 2-byte or 3-byte samples, so the bytes are "
           "damaged on the way (cable, USB adapter, another program on the port) or come from a lidar ydscope does "
           "not know";
  std::string why =
      f.headers == 0 ? "no AA 55 packet headers" : std::to_string(f.headers) + " stray AA 55 pairs, none a packet";
  why += ", no replies";
  if (f.top_byte_count * 10 >= f.window_bytes * 9) {
    char byte[8];
    std::snprintf(byte, sizeof byte, "0x%02X", f.top_byte);
    why += std::string(", nearly every byte ") + byte;
  }
  if (baud == 0)
    return arrive + ": the line looks like another baud (" + why + "); set the serial bridge to the " + model + "'s " +
           std::to_string(expected.default_baud) + " baud";
  return arrive + ": the line looks like another baud (" + why + "); " + baud_advice(expected, baud);
}

}  // namespace ydscope
