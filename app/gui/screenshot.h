#pragma once
// Saving what the window shows: the framebuffer as PNG, and the current lap as CSV.
#include <string>

#include "core/protocol/lap.h"
#include "ui/view/file_names.h"

namespace ydscope::gui {

// Reads the current framebuffer (after rendering, before the swap) and writes it as PNG.
// Returns an empty string on success, otherwise one sentence saying what failed.
std::string save_framebuffer_png(const std::string& path, int width, int height);

// One line per point: angle_deg,range_mm,flag. Empty string on success, otherwise a sentence.
std::string export_lap_csv(const std::string& path, const Lap& lap);

// Saved files get ui::timestamped_name (ui/view/file_names.h).
using ui::timestamped_name;

}  // namespace ydscope::gui
