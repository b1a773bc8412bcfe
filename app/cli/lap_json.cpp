#include "app/cli/lap_json.h"

#include <array>
#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstring>
#include <stdexcept>

#include "core/export/lap_text.h"
#include "core/text/json_string.h"

namespace ydscope::cli {

JsonOut::~JsonOut() {
  try {
    flush();
  } catch (...) {
  }
}

void JsonOut::string(std::string_view text) { append_json_string(text_, text); }

void JsonOut::flush() {
  // fflush too: stdout on a pipe is fully buffered, and a reader must get each line we hand over.
  if (!text_.empty() &&
      (std::fwrite(text_.data(), 1, text_.size(), file_) != text_.size() || std::fflush(file_) != 0)) {
    text_.clear();
    throw std::runtime_error("writing the output failed: " + std::string(std::strerror(errno)));
  }
  text_.clear();
}

namespace {
void write_type(JsonOut& out, std::string_view type, std::optional<std::string_view> source) {
  out.raw(R"({"type":)");
  out.string(type);
  if (source) {
    out.raw(R"(,"source":)");
    out.string(*source);
  }
}
}  // namespace

void write_lap(JsonOut& out, const Lap& lap, bool g1_info, std::optional<std::uint8_t> health, double t_s,
               std::optional<std::string_view> source) {
  write_type(out, "lap", source);
  out.raw(R"(,"index":)");
  out.integer(lap.index);
  out.raw(R"(,"t":)");
  out.fixed(t_s, 6);
  out.raw(R"(,"points":[)");
  bool first = true;
  for (const LapPoint& point : lap.points) {
    out.raw(first ? "[" : ",[");
    first = false;
    append_point_fields(out.buffer(), point);
    out.raw("]");
  }
  const bool trusted = lap.ct_info_trusted();
  out.raw(R"(],"scan_hz":)");
  // G1's CT channel, or the zero packet's CT of a G6/TG read as the field reads it.
  out.fixed_or_null(trusted ? lap.scan_hz : std::nullopt, 2);
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

void write_summary(JsonOut& out, const DecoderCounters& counters, const std::optional<std::string>& start,
                   std::optional<std::string_view> source) {
  write_summary_fields(out, counters, start, source);
  out.raw("}\n");
}

void write_summary_fields(JsonOut& out, const DecoderCounters& c, const std::optional<std::string>& start,
                          std::optional<std::string_view> source) {
  write_type(out, "summary", source);
  out.raw(R"(,"bytes":)");
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
