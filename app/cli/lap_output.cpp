#include "app/cli/lap_output.h"

#include <cstdio>

#include "app/common/arguments.h"
#include "core/export/lap_text.h"
#include "core/protocol/no_lap_reason.h"

namespace ydscope::cli {
namespace {

// The CLI names sources with letters, digits and _, but a recording may say anything.
void write_csv_field(JsonOut& out, std::string_view text) {
  if (text.find_first_of(",\"\r\n") == std::string_view::npos) {
    out.raw(text);
    return;
  }
  out.raw("\"");
  for (const char c : text) out.raw(c == '"' ? std::string_view("\"\"") : std::string_view(&c, 1));
  out.raw("\"");
}

}  // namespace

LapFormat parse_lap_format(const std::optional<std::string>& value, LapFormat fallback) {
  if (!value) return fallback;
  if (*value == "jsonl") return LapFormat::Jsonl;
  if (*value == "csv") return LapFormat::Csv;
  if (*value == "summary") return LapFormat::Summary;
  throw UsageError("--format must be jsonl, csv or summary, not '" + *value + "'");
}

LapPrinter::LapPrinter(JsonOut& out, LapFormat format, bool g1_info) : out_(out), format_(format), g1_info_(g1_info) {}

void LapPrinter::print(const Lap& lap) {
  print(lap, g1_info_ && lap.ct_info_trusted() ? lap.health_bits : std::nullopt);
}

void LapPrinter::print(const Lap& lap, std::optional<std::uint8_t> health) { print(lap, health, std::nullopt); }

void LapPrinter::print_from(std::string_view source, bool g1_info, const Lap& lap) {
  print(lap, g1_info && lap.ct_info_trusted() ? lap.health_bits : std::nullopt, source);
}

void LapPrinter::print(const Lap& lap, std::optional<std::uint8_t> health, std::optional<std::string_view> source) {
  if (format_ == LapFormat::Summary) return;
  if (!origin_ns_) origin_ns_ = lap.first_rx_ns;
  const double t_s = static_cast<double>(lap.last_rx_ns - *origin_ns_) * 1e-9;
  if (format_ == LapFormat::Jsonl) {
    write_lap(out_, lap, health, t_s, source);
    return;
  }
  if (!header_written_) {
    if (source) out_.raw("source,");
    out_.raw(kLapCsvHeader);
    header_written_ = true;
  }
  if (!source) {
    append_lap_csv_rows(out_.buffer(), lap.index, t_s, lap.points);
  } else {
    for (const LapPoint& point : lap.points) {  // the shared rows, each after its source column
      write_csv_field(out_, *source);
      out_.raw(",");
      append_lap_csv_rows(out_.buffer(), lap.index, t_s, {&point, 1});
    }
  }
  out_.maybe_flush();
}

void say_why_no_lap(const char* program, std::string_view model, const DecoderCounters& counters) {
  if (counters.laps > 0 || counters.bytes == 0) return;
  const std::string why = no_lap_reason(model, {counters.bytes, counters.packets, counters.zero_packets});
  std::fprintf(stderr, "%s: no complete lap: %s\n", program, why.c_str());
}

}  // namespace ydscope::cli
