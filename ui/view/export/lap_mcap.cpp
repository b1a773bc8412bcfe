#include "ui/view/export/lap_mcap.h"

#include <algorithm>

#include "core/export/mcap_recording_export.h"
#include "ui/view/export/whole_file.h"

namespace ydscope::ui {

ShownLapsMcap save_shown_laps_mcap(const LapHistory& history, std::size_t laps, Model model,
                                   const RecordingMetadata& metadata, std::int64_t rx_to_wall_ns,
                                   const std::string& path) {
  ShownLapsMcap result;
  auto file = McapRecordingExport::create(part_name(path), {}, result.error);
  if (!file) {
    result.error = finish_whole_file(path, result.error);  // nothing half-made is left
    return result;
  }
  file->metadata(metadata, 0);
  result.laps = std::min(laps, history.size());
  Lap lap;
  for (std::size_t age = result.laps; age-- > 0;) {
    const HistoryLap& shown = history.at_age(age);
    lap.index = shown.index;
    lap.points = shown.points;
    lap.first_rx_ns = shown.first_rx_ns;
    lap.last_rx_ns = shown.last_rx_ns;
    file->lap(lap, model, rx_to_wall_ns);
  }
  if (!file->finish()) result.error = "writing " + path + " failed: " + file->error();
  result.messages = file->statistics().message_count;
  file.reset();  // closed before it takes its name
  result.error = finish_whole_file(path, result.error);
  return result;
}

}  // namespace ydscope::ui
