#include "ui/view/settings/sidebar_tab.h"

namespace ydscope::ui {

std::string_view sidebar_tab_word(SidebarTab tab) {
  switch (tab) {
    case SidebarTab::Lidar: return "lidar";
    case SidebarTab::View: return "view";
    case SidebarTab::Statistics: return "statistics";
    case SidebarTab::Sources: return "sources";
  }
  return "lidar";
}

std::optional<SidebarTab> sidebar_tab_from_word(std::string_view word) {
  for (const SidebarTab tab : {SidebarTab::Lidar, SidebarTab::View, SidebarTab::Statistics, SidebarTab::Sources})
    if (word == sidebar_tab_word(tab)) return tab;
  return std::nullopt;
}

}  // namespace ydscope::ui
