#include "app/gui/watched_sectors.h"

#include <cstdio>

namespace ydscope::gui {

void restore_watched_sectors(std::vector<ui::SectorWatch>& sectors, const ui::ViewSettings& settings,
                             const std::optional<std::string>& command_line_sector) {
  for (const std::string& spec : settings.sectors) ui::watch_sector(sectors, spec);  // checked when read
  if (command_line_sector) {
    const std::string error = ui::watch_sector(sectors, *command_line_sector);
    if (!error.empty() && error.find("already") == std::string::npos)
      std::fprintf(stderr, "ydscope: %s\n", error.c_str());
  }
}

void follow_watched_sectors(const SourceList& sources, ui::ViewSettings& settings, ui::PolarView& view) {
  const std::vector<ui::SectorWatch>& sectors = sources.selected().model.sectors;
  const bool first = sources.selected_index() == 0;
  if (first) settings.sectors.clear();
  std::vector<ui::SectorShape> shapes;
  for (std::size_t i = 0; i < sectors.size(); ++i) {
    const Sector& s = sectors[i].sector();
    if (first) settings.sectors.push_back(sectors[i].spec());
    shapes.push_back({static_cast<float>(s.from_deg), static_cast<float>(s.width_deg()), "S" + std::to_string(i + 1)});
  }
  if (sources.several()) shapes.clear();
  view.set_sectors(std::move(shapes));
}

}  // namespace ydscope::gui
