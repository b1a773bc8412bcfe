#pragma once
// The laps on screen, frozen or live, saved as a file beside the app (E and Shift+E: CSV; M:
// MCAP with /scan and /points): the view's laps, never a newer one it has not shown. Each returns
// the status line's sentence: what was saved where, or why nothing was.
#include <cstddef>
#include <string>

#include "core/snapshot/session_snapshot.h"
#include "ui/view/scene/lap_history.h"

namespace ydscope::gui {

// The newest `laps` of `history` (one: the newest lap) as CSV.
std::string export_shown_laps_csv(const ui::LapHistory& history, std::size_t laps, bool frozen);
// Every lap of `history` as MCAP, described by the session's snapshot and the source's text.
std::string export_shown_laps_mcap(const ui::LapHistory& history, const SessionSnapshot& snapshot,
                                   const std::string& source_text, bool frozen);

}  // namespace ydscope::gui
