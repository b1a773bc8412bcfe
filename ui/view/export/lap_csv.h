#pragma once
// What the View panel's CSV export writes: the laps on screen (frozen or live), never a newer lap
// the view has not shown. Oldest lap first, one row per point, written by core/export/lap_text.h
// as ydscope-cli's --format csv (decode, scan, replay) is, so a file from either reads the same: t is
// seconds from the first byte of the oldest exported lap to the byte that closed the row's lap.
#include <cstddef>
#include <string>

#include "core/export/lap_text.h"
#include "ui/view/scene/lap_history.h"

namespace ydscope::ui {

// The newest `laps` of `history` (all it holds when it holds fewer) as CSV with kLapCsvHeader.
std::string shown_laps_csv(const LapHistory& history, std::size_t laps);

}  // namespace ydscope::ui
