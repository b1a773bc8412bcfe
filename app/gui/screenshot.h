#pragma once
// Saving what the window shows: the framebuffer as PNG, and the laps on screen as CSV.
#include <string>

#include "core/protocol/lap.h"
#include "ui/view/export/file_names.h"

namespace ydscope::gui {

// Reads the current framebuffer (after rendering, before the swap) and writes it as PNG.
// Returns an empty string on success, otherwise one sentence saying what failed.
std::string save_framebuffer_png(const std::string& path, int width, int height);

// Writes `text` (the CSV of ui/view/export/lap_csv.h). Empty string on success, otherwise a sentence.
std::string save_text_file(const std::string& path, const std::string& text);

// Saved files get ui::timestamped_name (ui/view/export/file_names.h).
using ui::timestamped_name;

}  // namespace ydscope::gui
