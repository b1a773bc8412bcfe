#include "app/gui/shown_laps_export.h"

#include <chrono>
#include <optional>

#include "core/session/recording_control.h"
#include "app/gui/screenshot.h"
#include "ui/view/export/lap_csv.h"
#include "ui/view/export/lap_mcap.h"

namespace ydscope::gui {
namespace {

// "lap 12" or "8 laps (5 to 12)", and " as frozen" while frozen.
std::string shown_laps_words(const ui::LapHistory& history, std::size_t laps, bool frozen) {
  const std::string what = laps == 1
                               ? "lap " + std::to_string(history.newest().index)
                               : std::to_string(laps) + " laps (" + std::to_string(history.at_age(laps - 1).index) +
                                     " to " + std::to_string(history.newest().index) + ")";
  return what + (frozen ? " as frozen" : "");
}

constexpr const char* kNothingShown = "no lap to export yet.";

}  // namespace

std::string export_shown_laps_csv(const ui::LapHistory& history, std::size_t laps, bool frozen) {
  if (history.empty()) return kNothingShown;
  const std::string path = timestamped_name("csv");
  const std::string error = save_text_file(path, ui::shown_laps_csv(history, laps));
  return error.empty() ? "exported " + shown_laps_words(history, laps, frozen) + " to " + path : error;
}

std::string export_shown_laps_mcap(const ui::LapHistory& history, const SessionSnapshot& s,
                                   const std::string& source_text, bool frozen) {
  if (history.empty()) return kNothingShown;
  const Model model = s.device && s.device->profile ? s.device->profile->model : Model::G6;
  // The laps carry steady-clock receive times; the file wants wall-clock ones.
  const auto wall_ns =
      std::chrono::duration_cast<std::chrono::nanoseconds>(std::chrono::system_clock::now().time_since_epoch());
  const auto steady =
      std::chrono::duration_cast<std::chrono::nanoseconds>(std::chrono::steady_clock::now().time_since_epoch());
  const std::string path = timestamped_name("mcap");
  const ui::ShownLapsMcap saved = ui::save_shown_laps_mcap(
      history, history.size(), model,
      recording_metadata_of(s, source_text, s.distance_scale > 0 ? std::optional(s.distance_scale) : std::nullopt),
      (wall_ns - steady).count(), path);
  if (!saved.error.empty()) return saved.error;
  return "exported " + shown_laps_words(history, saved.laps, frozen) + " to " + path + " (" +
         std::to_string(saved.messages) + " messages on /scan and /points)";
}

}  // namespace ydscope::gui
