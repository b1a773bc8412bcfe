// App, the watched sectors: one SectorWatch per sector in the view model (each source its own),
// fed every shown lap (drain_laps), outlined on the view, added from the Sectors panel or a
// Shift+drag, and remembered as settings.ini's `sector = ...` lines.
#include <algorithm>
#include <cstdio>

#include "app/gui/app.h"

namespace ydscope::gui {

void App::restore_sectors() {
  for (const std::string& spec : settings_.sectors) ui::watch_sector(model().sectors, spec);  // checked when read
  if (options_.sector) {
    const std::string error = ui::watch_sector(model().sectors, *options_.sector);
    if (!error.empty() && error.find("already") == std::string::npos)
      std::fprintf(stderr, "ydscope: %s\n", error.c_str());
  }
  sync_sectors();
}

void App::unwatch_sector(std::size_t index) {
  ui::UiModel& m = model();
  if (index >= m.sectors.size()) return;
  m.sectors.erase(m.sectors.begin() + static_cast<std::ptrdiff_t>(index));
  sync_sectors();
}

void App::sync_sectors() {
  ui::UiModel& m = model();
  // Each source watches its own sectors; the first one's are remembered (a lone lidar is first).
  if (selected_ == 0) settings_.sectors.clear();
  std::vector<ui::SectorShape> shapes;
  for (std::size_t i = 0; i < m.sectors.size(); ++i) {
    const Sector& s = m.sectors[i].sector();
    if (selected_ == 0) settings_.sectors.push_back(m.sectors[i].spec());
    shapes.push_back({static_cast<float>(s.from_deg), static_cast<float>(s.width_deg()), "S" + std::to_string(i + 1)});
  }
  // A sector is angles round one lidar: outlined only while the view is drawn round one.
  if (sources_.size() > 1) shapes.clear();
  view_->set_sectors(std::move(shapes));
}

}  // namespace ydscope::gui
