#include "app/cli/lap_json.h"

#include <array>
#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstring>
#include <stdexcept>

#include "core/text/json_string.h"

namespace ydscope::cli {

JsonOut::~JsonOut() {
  try {
    flush();
  } catch (...) {
  }
}

void JsonOut::integer(std::uint64_t value) {
  std::array<char, 24> digits;
  const auto end = std::to_chars(digits.data(), digits.data() + digits.size(), value).ptr;
  text_.append(digits.data(), end);
}

void JsonOut::fixed(double value, int decimals) {
  // Scaled-integer formatting: to_chars' exact fixed-precision path dominated jsonl output time,
  // and points need only a few decimals. Ties round to even, as to_chars does; trailing zeros are trimmed.
  static constexpr std::array<double, 7> kScale{1, 10, 100, 1e3, 1e4, 1e5, 1e6};
  const int places = decimals < 0 ? 0 : (decimals > 6 ? 6 : decimals);
  const double scaled = std::nearbyint(std::fabs(value) * kScale[static_cast<std::size_t>(places)]);
  if (!std::isfinite(value) || scaled >= 9e15) {  // beyond exact integers: let to_chars handle it
    std::array<char, 352> digits;
    const auto end = std::to_chars(digits.data(), digits.data() + digits.size(), value,
                                   std::chars_format::fixed, places).ptr;
    text_.append(digits.data(), end);
    return;
  }
  auto units = static_cast<std::uint64_t>(scaled);
  if (units == 0) {
    text_.push_back('0');
    return;
  }
  if (value < 0) text_.push_back('-');
  std::array<char, 8> fraction{};
  int fraction_digits = places;
  for (int i = places - 1; i >= 0; --i) {
    fraction[static_cast<std::size_t>(i)] = static_cast<char>('0' + units % 10);
    units /= 10;
  }
  while (fraction_digits > 0 && fraction[static_cast<std::size_t>(fraction_digits - 1)] == '0') --fraction_digits;
  integer(units);
  if (fraction_digits > 0) {
    text_.push_back('.');
    text_.append(fraction.data(), static_cast<std::size_t>(fraction_digits));
  }
}

void JsonOut::string(std::string_view text) { append_json_string(text_, text); }

void JsonOut::flush() {
  // fflush too: stdout on a pipe is fully buffered, and a reader must get each line we hand over.
  if (!text_.empty() && (std::fwrite(text_.data(), 1, text_.size(), file_) != text_.size() || std::fflush(file_) != 0)) {
    text_.clear();
    throw std::runtime_error("writing the output failed: " + std::string(std::strerror(errno)));
  }
  text_.clear();
}

void write_point_fields(JsonOut& out, const LapPoint& point) {
  // 359.99996 rounds to "360": print the same direction as 0 to stay in [0, 360).
  const auto degrees = static_cast<double>(point.angle_deg);
  out.fixed(degrees >= 359.99995 ? 0.0 : degrees, 4);
  out.raw(",");
  out.fixed(point.range_mm, 2);
  out.raw(",");
  out.integer(static_cast<std::uint64_t>(point.flag));
}

void write_lap(JsonOut& out, const Lap& lap, bool g1_info, std::optional<std::uint8_t> health, double t_s) {
  out.raw(R"({"type":"lap","index":)");
  out.integer(lap.index);
  out.raw(R"(,"t":)");
  out.fixed(t_s, 6);
  out.raw(R"(,"points":[)");
  bool first = true;
  for (const LapPoint& point : lap.points) {
    out.raw(first ? "[" : ",[");
    first = false;
    write_point_fields(out, point);
    out.raw("]");
  }
  const bool trusted = lap.ct_info_trusted();
  out.raw(R"(],"scan_hz":)");
  out.fixed_or_null(g1_info && trusted ? lap.scan_hz : std::nullopt, 2);
  out.raw(R"(,"health":)");
  out.integer_or_null(health);
  out.raw(R"(,"crc_ok":)");
  out.raw(lap.crc == CrcVerdict::Ok ? "true" : lap.crc == CrcVerdict::Mismatch ? "false" : "null");
  out.raw(R"(,"packets":)");
  out.integer(lap.packets);
  out.raw(R"(,"checksum_errors":)");
  out.integer(lap.checksum_errors);
  if (lap.cut_points > 0) {  // only a damaged stream: a sound lap's line stays as it was
    out.raw(R"(,"cut_points":)");
    out.integer(lap.cut_points);
  }
  out.raw("}\n");
  out.maybe_flush();
}

void write_summary(JsonOut& out, const DecoderCounters& counters, const std::optional<std::string>& start) {
  write_summary_fields(out, counters, start);
  out.raw("}\n");
}

void write_summary_fields(JsonOut& out, const DecoderCounters& c, const std::optional<std::string>& start) {
  out.raw(R"({"type":"summary","bytes":)");
  out.integer(c.bytes);
  out.raw(R"(,"packets":)");
  out.integer(c.packets);
  out.raw(R"(,"checksum_errors":)");
  out.integer(c.checksum_errors);
  out.raw(R"(,"zero_packets":)");
  out.integer(c.zero_packets);
  out.raw(R"(,"laps":)");
  out.integer(c.laps);
  if (c.overflow_points > 0) {
    out.raw(R"(,"cut_points":)");
    out.integer(c.overflow_points);
  }
  if (start) {
    out.raw(R"(,"start":)");
    out.string(*start);
  }
}

}  // namespace ydscope::cli
