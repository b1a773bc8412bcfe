#include "app/cli/health_watch.h"

#include "core/session/device_probe.h"

namespace ydscope::cli {
namespace {

bool same_answer(const HealthReport& a, const HealthReport& b) {
  return a.command == b.command && a.status == b.status && a.error_code == b.error_code;
}

// What the user may do about it, by how bad it is.
const char* advice(HealthLevel level) {
  switch (level) {
    case HealthLevel::Error:
      return "; its laps may be wrong (the lidar's manual says what this means; power-cycling may clear it)";
    case HealthLevel::Warning: return "; its laps may be degraded (the lidar's manual says what this means)";
    case HealthLevel::Ok: return "";
  }
  return "";
}

}  // namespace

void HealthWatch::observe_answer(const std::optional<HealthReport>& answer) {
  if (!answer || (last_answer_ && same_answer(*answer, *last_answer_))) return;
  last_answer_ = answer;
  const std::string command = command_bytes_text(answer->command);
  note({health_level(answer->command, answer->status, answer->error_code), answer->summary, command,
        "the lidar answered " + command + " with"});
}

void HealthWatch::observe_lap(const Lap& lap) {
  if (!lap.health_bits || !lap.ct_info_trusted()) return;
  const HealthReport bits = make_health_report(Command::HealthStatusBits, {*lap.health_bits, 0});
  note({health_bits_level(*lap.health_bits), bits.summary, "CT",
        "lap " + std::to_string(lap.index) + "'s CT health says"});
}

void HealthWatch::note(Observation o) {
  // The same words from another source (A5 92, then each lap's CT bits) are no news.
  const bool changed = !current_ || current_->level != o.level || current_->summary != o.summary;
  if (changed && (o.level != HealthLevel::Ok || (current_ && current_->level != HealthLevel::Ok))) {
    const std::string label =
        o.level == HealthLevel::Ok ? "health ok again" : "health " + std::string(health_level_name(o.level));
    std::fprintf(err_, "%s%s: %s: %s %s%s\n", clear_line_ ? "\r\033[K" : "", program_.c_str(), label.c_str(),
                 o.where.c_str(), o.summary.c_str(), advice(o.level));
    std::fflush(err_);
  }
  if (!worst_ || o.level > worst_->level) worst_ = o;
  if (changed) current_ = std::move(o);
}

std::optional<std::uint8_t> HealthWatch::lap_health(const Lap& lap, bool ct_info) const {
  if (ct_info) return lap.ct_info_trusted() ? lap.health_bits : std::nullopt;
  if (last_answer_) return last_answer_->status;
  return std::nullopt;
}

void HealthWatch::write_summary_field(JsonObject& summary) const {
  if (!worst_) {
    summary.field("health", nullptr);
    return;
  }
  summary.object("health")
      .field("level", health_level_name(worst_->level))
      .field("source", worst_->source)
      .field("summary", worst_->summary);
}

std::string HealthWatch::summary_note() const {
  if (!worst_ || worst_->level == HealthLevel::Ok) return {};
  return "; the lidar reported a health " + std::string(health_level_name(worst_->level)) + ": " + worst_->summary +
         " (" + worst_->source + ")";
}

}  // namespace ydscope::cli
