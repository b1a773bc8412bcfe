#pragma once
// The JSON lines `decode` defined for laps and its summary (schema in `ydscope-cli decode --help`),
// shared by every subcommand that prints laps (decode, scan) so they all speak one schema.
#include <atomic>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <optional>
#include <string>
#include <string_view>

#include "core/protocol/lap.h"
#include "core/protocol/scan_decoder.h"
#include "core/text/json_writer.h"

namespace ydscope::cli {

// The text a command prints, kept until kFlushAt bytes stand: JSON lines are written into buffer()
// with core/text/json_writer.h, CSV rows with core/export/lap_text.h.
class JsonOut {
 public:
  static constexpr std::size_t kFlushAt = 1 << 16;

  explicit JsonOut(std::FILE* file) : file_(file) { text_.reserve(2 * kFlushAt); }
  // A writer that gives up once `give_up` is set, however long its reader has stopped taking
  // output: flush() then throws instead of waiting on a full pipe (scan, which must stop the lidar).
  JsonOut(std::FILE* file, const std::atomic<bool>& give_up) : JsonOut(file) { give_up_ = &give_up; }
  ~JsonOut();  // flushes; a failure there is lost, so call flush() yourself to see it

  void raw(std::string_view text) { text_.append(text); }
  // The text not yet written, for the writers to append to.
  std::string& buffer() { return text_; }
  void maybe_flush() {
    if (text_.size() >= kFlushAt) flush();
  }
  // Throws std::runtime_error with a sentence when writing fails.
  void flush();

 private:
  std::FILE* file_;
  const std::atomic<bool>* give_up_ = nullptr;
  std::string text_;
};

// {"type":"lap",...} and a newline; `health` what is known of the unit's health (the lap's own CT, or
// a live session's answer; the printer leaves it out where the model's CT carries none), t_s the lap's time
// (LapPrinter says which). Commands print laps through LapPrinter (lap_output.h).
// `source`: the lidar of a several-lidar recording, as a "source" field after "type"; none for one.
void write_lap(JsonOut& out, const Lap& lap, std::optional<std::uint8_t> health, double t_s,
               std::optional<std::string_view> source = std::nullopt);
// {"type":"summary","bytes":B,"packets":P,"checksum_errors":E,"zero_packets":Z,"laps":L
//  [,"cut_points":C][,"start":"ISO 8601 UTC"]} and a newline; start: the wall-clock time of the
// stream's start, when it is known.
// `source` as in write_lap: one summary per source of a several-lidar recording.
void write_summary(JsonOut& out, const DecoderCounters& counters, const std::optional<std::string>& start,
                   std::optional<std::string_view> source = std::nullopt);
// Its fields, for a summary with more fields.
void write_summary_fields(JsonObject& line, const DecoderCounters& counters, const std::optional<std::string>& start,
                          std::optional<std::string_view> source = std::nullopt);

}  // namespace ydscope::cli
