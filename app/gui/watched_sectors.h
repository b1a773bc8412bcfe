#pragma once
// The watched sectors: one SectorWatch per sector in each source's panel model, fed every lap it
// measures, added from the Sectors panel or a Shift+drag, outlined on the view, and remembered as
// settings.ini's `sector = ...` lines.
#include <optional>
#include <string>
#include <vector>

#include "app/gui/source_list.h"
#include "ui/render/polar_view.h"
#include "ui/view/history/sector_watch.h"
#include "ui/view/settings/settings.h"

namespace ydscope::gui {

// The remembered sectors, then --sector's (a mistake in it goes to stderr; one already
// remembered is not a mistake).
void restore_watched_sectors(std::vector<ui::SectorWatch>& sectors, const ui::ViewSettings& settings,
                             const std::optional<std::string>& command_line_sector);
// After a change of sectors or sources: settings.ini's list follows the first source's sectors
// (a lone lidar is first), and the view outlines the selected source's while it draws one lidar
// round itself (a sector is angles round one lidar).
void follow_watched_sectors(const SourceList& sources, ui::ViewSettings& settings, ui::PolarView& view);

}  // namespace ydscope::gui
