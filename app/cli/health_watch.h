#pragma once
// What scan and record say about the lidar's health while they run. Two sources: the session's
// health answer (A5 91 on G6/TG, A5 92 on G1, asked at start-up) and, on G1, every lap's CT health
// bits (only laps whose CRC8 held). A warning or an error is one line on stderr when it first shows
// and again whenever it changes (back to ok too); the worst seen goes into the summary and decides
// the exit status (kExitLidarFault for an error).
#include <cstdint>
#include <cstdio>
#include <optional>
#include <string>

#include "core/session/session.h"
#include "core/protocol/health_level.h"
#include "core/protocol/lap.h"
#include "core/text/json_writer.h"

namespace ydscope::cli {

class HealthWatch {
 public:
  // `program` prefixes each line: "ydscope-cli scan".
  explicit HealthWatch(std::string program, std::FILE* err = stderr) : program_(std::move(program)), err_(err) {}
  // Each line first clears the terminal line (record's progress is drawn there in place).
  void clear_line_first(bool clear) { clear_line_ = clear; }

  // Call with every snapshot's health; only a new answer counts.
  void observe_answer(const std::optional<HealthReport>& answer);
  // A lap's CT health bits (G1), when it carries them and its CRC8 held.
  void observe_lap(const Lap& lap);

  // The health a lap line carries: the lap's own CT bits when the model has them (as decode
  // prints them), else the status byte of the session's last health answer; empty when unknown.
  std::optional<std::uint8_t> lap_health(const Lap& lap, bool ct_info) const;

  // Error when any observation was an error; empty when nothing was known all run.
  std::optional<HealthLevel> worst() const { return worst_ ? std::optional(worst_->level) : std::nullopt; }
  // "health":{"level":"error","source":"A5 91","summary":"error (error code 0x00FF)"} for the
  // worst observation of the run (the first at that level), or "health":null.
  void write_summary_field(JsonObject& summary) const;
  // "; the lidar reported a health error: error (error code 0x00FF) (A5 91)" for the worst
  // observation when it was a warning or an error; empty otherwise.
  std::string summary_note() const;

 private:
  struct Observation {
    HealthLevel level = HealthLevel::Ok;
    std::string summary;  // "ok", "error (error code 0x00FF)", "abnormal: sensor, encoder"
    std::string source;   // "A5 91", "A5 92", "CT"
    std::string where;    // "the lidar answered A5 91 with", "lap 12's CT health says"
  };
  void note(Observation o);

  std::string program_;
  std::FILE* err_;
  bool clear_line_ = false;
  std::optional<HealthReport> last_answer_;
  std::optional<Observation> current_;
  std::optional<Observation> worst_;
};

}  // namespace ydscope::cli
