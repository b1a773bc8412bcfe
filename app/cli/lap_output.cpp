#include "app/cli/lap_output.h"

#include "app/common/arguments.h"
#include "core/export/lap_text.h"

namespace ydscope::cli {

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

void LapPrinter::print(const Lap& lap, std::optional<std::uint8_t> health) {
  if (format_ == LapFormat::Summary) return;
  if (!origin_ns_) origin_ns_ = lap.first_rx_ns;
  const double t_s = static_cast<double>(lap.last_rx_ns - *origin_ns_) * 1e-9;
  if (format_ == LapFormat::Jsonl) {
    write_lap(out_, lap, g1_info_, health, t_s);
    return;
  }
  if (!header_written_) {
    out_.raw(kLapCsvHeader);
    header_written_ = true;
  }
  append_lap_csv_rows(out_.buffer(), lap.index, t_s, lap.points);
  out_.maybe_flush();
}

}  // namespace ydscope::cli
