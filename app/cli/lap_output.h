#pragma once
// How decode, scan and replay print laps: JSON lines (the schema in `decode --help`), CSV (a header,
// then one row per point), or only the summary. One place for --format, so the three commands
// accept the same words and print the same lines.
//
// Every lap carries `t`: seconds from the first byte of the first lap printed to the byte that
// closed this lap, from the receive times the decoder was given: live ones in scan, the recorded
// ones in decode and replay of a .ydrec (so both print the same t, at any replay speed), and for a
// raw capture the times the model's baud rate would deliver its bytes at.
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>

#include "app/cli/lap_json.h"
#include "core/protocol/lap.h"

namespace ydscope::cli {

enum class LapFormat { Jsonl, Csv, Summary };

// The --format value (empty: `fallback`); anything else is a UsageError naming the three.
LapFormat parse_lap_format(const std::optional<std::string>& value, LapFormat fallback);

class LapPrinter {
 public:
  // g1_info: the model carries CT information (scan_hz, health).
  LapPrinter(JsonOut& out, LapFormat format, bool g1_info);

  // With the health the lap's own CT reports (decode, replay), or the one a live session knows.
  void print(const Lap& lap);
  void print(const Lap& lap, std::optional<std::uint8_t> health);
  // A lap of one source of a several-lidar recording: JSON gets a "source" field, CSV a first
  // column "source" (its header says so); t counts from the first lap of any source.
  void print_from(std::string_view source, bool g1_info, const Lap& lap);

  // The summary line follows the laps in jsonl and summary; a CSV holds only its rows.
  bool wants_summary() const { return format_ != LapFormat::Csv; }

 private:
  void print(const Lap& lap, std::optional<std::uint8_t> health, std::optional<std::string_view> source);

  JsonOut& out_;
  LapFormat format_;
  bool g1_info_;
  bool header_written_ = false;
  std::optional<std::int64_t> origin_ns_;
};

// Input read to its end without one complete lap: why, on stderr ("PROGRAM: no complete lap:
// its 3 G6 scan packets (72 bytes) are too short for a lap, ..."; core/protocol/no_lap_reason.h).
// Nothing when a lap came, or when nothing was read.
void say_why_no_lap(const char* program, std::string_view model, const DecoderCounters& counters);

}  // namespace ydscope::cli
